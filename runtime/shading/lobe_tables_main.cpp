// Writes runtime/shading/built_lobe_tables.cpp, the tables of shading/built_lobe_tables.hpp
// computed here: each float as a hexadecimal literal, which the compiler reads back exactly.
#include "shading/lobe_table.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

void writeTable(std::ostream& out, const char* name, const std::vector<float>& table) {
    out << "const float " << name << "[] = {\n";
    char literal[64];
    for (size_t i = 0; i < table.size(); ++i) {
        if (!std::isfinite(table[i])) throw std::runtime_error(std::string(name) + ": a texel is not finite");
        std::snprintf(literal, sizeof literal, "%af,%c", double(table[i]), i % 8 == 7 ? '\n' : ' ');
        out << literal;
    }
    out << "};\n\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: lobe_tables OUTPUT.cpp\n";
        return 2;
    }
    try {
        using namespace iblkit::shading;
        std::ofstream out(argv[1], std::ios::binary);
        out << "// Written by runtime/shading/lobe_tables_main.cpp (cmake --build build --target refresh-lobe-tables);\n"
               "// do not edit. tests/shading/built_lobe_tables_test.cpp checks it against the computation.\n"
               "#include \"shading/built_lobe_tables.hpp\"\n\nnamespace iblkit::shading {\nnamespace {\n\n";
        writeTable(out, "kByNdotL", lobeTable(kLobeTableSize, LobeWeighting::NdotL));
        writeTable(out, "kByG1", lobeTable(kLobeTableSize, LobeWeighting::G1));
        out << "} // namespace\n\nstd::span<const float> builtLobeTable(LobeWeighting weighting) {\n"
               "    return weighting == LobeWeighting::G1 ? std::span<const float>(kByG1) : std::span<const float>(kByNdotL);\n"
               "}\n\n} // namespace iblkit::shading\n";
        out.close();
        if (!out) throw std::runtime_error(std::string("cannot write ") + argv[1]);
    } catch (const std::exception& error) {
        std::remove(argv[1]);
        std::cerr << "lobe_tables: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
