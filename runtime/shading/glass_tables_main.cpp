// Writes runtime/shading/built_glass_tables.cpp, the tables of shading/built_glass_tables.hpp
// computed here: each float as a hexadecimal literal, which the compiler reads back exactly.
#include "shading/sphere_transmission.hpp"
#include "shading/transmission_table.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

void writeTable(std::ostream& out, const char* function, const std::vector<float>& table) {
    out << "std::span<const float> " << function << "() {\n    static const float table[] = {\n";
    char literal[64];
    for (size_t i = 0; i < table.size(); ++i) {
        if (!std::isfinite(table[i])) throw std::runtime_error(std::string(function) + ": a texel is not finite");
        std::snprintf(literal, sizeof literal, "%af,%c", double(table[i]), i % 8 == 7 ? '\n' : ' ');
        out << literal;
    }
    out << "};\n    return table;\n}\n\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: glass_tables OUTPUT.cpp\n";
        return 2;
    }
    try {
        using namespace iblkit::shading;
        std::ofstream out(argv[1], std::ios::binary);
        out << "// Written by runtime/shading/glass_tables_main.cpp (cmake --build build --target refresh-glass-tables);\n"
               "// do not edit. tests/shading/built_glass_tables_test.cpp checks it against the computation.\n"
               "#include \"shading/built_glass_tables.hpp\"\n\nnamespace iblkit::shading {\n\n";
        writeTable(out, "builtTransmissionTable", transmissionTable(kTransmissionTableSize));
        writeTable(out, "builtSphereTransmissionTable", sphereTransmissionTable(kTransmissionTableSize));
        out << "} // namespace iblkit::shading\n";
        out.close();
        if (!out) throw std::runtime_error(std::string("cannot write ") + argv[1]);
    } catch (const std::exception& error) {
        std::remove(argv[1]);
        std::cerr << "glass_tables: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
