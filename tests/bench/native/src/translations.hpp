#pragma once

// Factories of the seven translations, one per source file, collected by programs().

#include "eposp/bench/native/program.hpp"

#include <memory>

namespace eposp::bench::native {

std::unique_ptr<Program> make_bubble_sort();
std::unique_ptr<Program> make_sieve();
std::unique_ptr<Program> make_crc32();
std::unique_ptr<Program> make_pid_plant();
std::unique_ptr<Program> make_conveyor_fsm();
std::unique_ptr<Program> make_fb_channels();
std::unique_ptr<Program> make_strings();

} // namespace eposp::bench::native
