#include "eposp/drives/escon2/io/two_point_scaling.hpp"

namespace eposp::drives::escon2 {

double TwoPointScaling::apply(double input) const {
    if (second_input == first_input) {
        return first_value;
    }
    return first_value +
           (input - first_input) * (second_value - first_value) / (second_input - first_input);
}

} // namespace eposp::drives::escon2
