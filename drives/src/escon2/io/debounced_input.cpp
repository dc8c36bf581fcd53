#include "eposp/drives/escon2/io/debounced_input.hpp"

namespace eposp::drives::escon2 {

void DebouncedInput::settle(double now) {
    if (pin_ != filtered_ && now - since_ > filter_time_) {
        filtered_ = pin_;
    }
}

void DebouncedInput::set_level(bool high, double now) {
    settle(now); // a level held long enough before this change counts
    if (high != pin_) {
        pin_ = high;
        since_ = now;
    }
}

bool DebouncedInput::level(double now) {
    settle(now);
    return filtered_;
}

} // namespace eposp::drives::escon2
