// Writes runtime/shading/built_glass_tables.cpp, the tables of shading/built_glass_tables.hpp
// computed here.
#include "shading/sphere_transmission.hpp"
#include "shading/table_file_writer.hpp"
#include "shading/transmission_table.hpp"

namespace {

void writeTable(std::ostream& out, const char* function, const std::vector<float>& table) {
    out << "std::span<const float> " << function << "() {\n    static const float table[] = {\n";
    iblkit::shading::writeFloatLiterals(out, function, table);
    out << "};\n    return table;\n}\n\n";
}

} // namespace

int main(int argc, char** argv) {
    using namespace iblkit::shading;
    return writeTableFile(argc, argv, "glass_tables", [](std::ostream& out) {
        out << "// Written by runtime/shading/glass_tables_main.cpp (cmake --build build --target refresh-glass-tables);\n"
               "// do not edit. tests/shading/built_glass_tables_test.cpp checks it against the computation.\n"
               "#include \"shading/built_glass_tables.hpp\"\n\nnamespace iblkit::shading {\n\n";
        writeTable(out, "builtTransmissionTable", transmissionTable(kTransmissionTableSize));
        writeTable(out, "builtSphereTransmissionTable", sphereTransmissionTable(kTransmissionTableSize));
        out << "} // namespace iblkit::shading\n";
    });
}
