// Writes runtime/shading/built_lobe_tables.cpp, the tables of shading/built_lobe_tables.hpp
// computed here.
#include "shading/lobe_table.hpp"
#include "shading/table_file_writer.hpp"

namespace {

void writeTable(std::ostream& out, const char* name, const std::vector<float>& table) {
    out << "const float " << name << "[] = {\n";
    iblkit::shading::writeFloatLiterals(out, name, table);
    out << "};\n\n";
}

} // namespace

int main(int argc, char** argv) {
    using namespace iblkit::shading;
    return writeTableFile(argc, argv, "lobe_tables", [](std::ostream& out) {
        out << "// Written by runtime/shading/lobe_tables_main.cpp (cmake --build build --target refresh-lobe-tables);\n"
               "// do not edit. tests/shading/built_lobe_tables_test.cpp checks it against the computation.\n"
               "#include \"shading/built_lobe_tables.hpp\"\n\nnamespace iblkit::shading {\nnamespace {\n\n";
        writeTable(out, "kByNdotL", lobeTable(kLobeTableSize, LobeWeighting::NdotL));
        writeTable(out, "kByG1", lobeTable(kLobeTableSize, LobeWeighting::G1));
        out << "} // namespace\n\nstd::span<const float> builtLobeTable(LobeWeighting weighting) {\n"
               "    return weighting == LobeWeighting::G1 ? std::span<const float>(kByG1) : std::span<const float>(kByNdotL);\n"
               "}\n\n} // namespace iblkit::shading\n";
    });
}
