// Writes the EDS of the simulated EPOS2 to the file given, so that the shipped file is always
// a fresh export (tests/drives checks that it is).
#include "eposp/drives/epos2/epos2_eds.hpp"

#include <fmt/format.h>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 2) {
        fmt::print(stderr, "usage: {} <output.eds>\n", argv[0]);
        return 2;
    }
    std::ofstream out(argv[1], std::ios::binary);
    out << eposp::drives::epos2::epos2_eds();
    out.close();
    if (!out) {
        fmt::print(stderr, "{}: cannot write {}\n", argv[0], argv[1]);
        return 1;
    }
    return 0;
}
