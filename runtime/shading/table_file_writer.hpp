#pragma once

// What the table generators (glass_tables_main.cpp, lobe_tables_main.cpp) share: floats written
// as hexadecimal literals, which the compiler reads back exactly, and one output file written
// whole or removed.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace iblkit::shading {

// `table`'s values, eight to a line, each followed by a comma. Throws for one that is not finite.
inline void writeFloatLiterals(std::ostream& out, const std::string& name, const std::vector<float>& table) {
    char literal[64];
    for (size_t i = 0; i < table.size(); ++i) {
        if (!std::isfinite(table[i])) throw std::runtime_error(name + ": a texel is not finite");
        std::snprintf(literal, sizeof literal, "%af,%c", double(table[i]), i % 8 == 7 ? '\n' : ' ');
        out << literal;
    }
}

// A generator's main: `tool OUTPUT.cpp` writes the file with `write`, or removes it and says why.
inline int writeTableFile(int argc, char** argv, const std::string& tool, const std::function<void(std::ostream&)>& write) {
    if (argc != 2) {
        std::cerr << "usage: " << tool << " OUTPUT.cpp\n";
        return 2;
    }
    try {
        std::ofstream out(argv[1], std::ios::binary);
        write(out);
        out.close();
        if (!out) throw std::runtime_error(std::string("cannot write ") + argv[1]);
    } catch (const std::exception& error) {
        std::remove(argv[1]);
        std::cerr << tool << ": " << error.what() << "\n";
        return 1;
    }
    return 0;
}

} // namespace iblkit::shading
