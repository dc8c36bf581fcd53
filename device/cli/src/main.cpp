#include "cli.hpp"

int main(int argc, char** argv) {
    return eposp::device::run_cli(argc, argv);
}
