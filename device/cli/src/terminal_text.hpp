#pragma once

#include <string>
#include <string_view>

namespace eposp::device::cli {

/// `text` with every control character but newline and tab written as `\xNN`, so that bytes from
/// a source or an image (an escape sequence, a carriage return) cannot drive the terminal.
std::string terminal_text(std::string_view text);

} // namespace eposp::device::cli
