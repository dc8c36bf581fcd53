#include "cli.hpp"
#include "last_resort.hpp"

int main(int argc, char** argv) {
    return eposp::device::cli::with_last_resort_handler(
        [&] { return eposp::device::run_cli(argc, argv); });
}
