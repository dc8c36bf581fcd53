#include "eposp/device/axis_plot.hpp"

#include <algorithm>
#include <charconv>
#include <fmt/format.h>
#include <map>

namespace eposp::device {

namespace {

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> cells;
    for (std::size_t start = 0;;) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string_view::npos) {
            return cells;
        }
        start = comma + 1;
    }
}

bool number(std::string_view text, double& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

bool number_at(const std::vector<std::string_view>& cells, std::ptrdiff_t column, double& value) {
    return number(cells[static_cast<std::size_t>(column)], value);
}

// The drawing: one panel per quantity and axis, stacked.
constexpr double kWidth = 960;
constexpr double kLeft = 90;
constexpr double kRight = 20;
constexpr double kPanel = 150;
constexpr double kGap = 40;
constexpr double kBand = 14;
constexpr std::size_t kMostPoints = 2000; ///< per line; longer series are thinned

std::string_view colour_of(std::string_view state) {
    static const std::map<std::string_view, std::string_view> kColours{
        {"Disabled", "#bbbbbb"},       {"Standstill", "#7fbf7f"},       {"Homing", "#bf9fdf"},
        {"DiscreteMotion", "#6fa8dc"}, {"ContinuousMotion", "#f6b26b"}, {"Stopping", "#ffd966"},
        {"ErrorStop", "#e06666"}};
    const auto it = kColours.find(state);
    return it == kColours.end() ? "#eeeeee" : it->second;
}

struct Panel {
    std::string_view title;
    const std::vector<double>* values;
    std::string_view colour;
};

void draw_panel(std::string& svg, const AxisSeries& axis, const Panel& panel, double top, double t0,
                double t1) {
    const auto [low_it, high_it] = std::minmax_element(panel.values->begin(), panel.values->end());
    double low = *low_it;
    double high = *high_it;
    if (high - low < 1e-9) {
        low -= 1;
        high += 1;
    }
    const double width = kWidth - kLeft - kRight;
    const auto x = [&](double t) {
        return kLeft + (t - t0) / (t1 - t0) * width;
    };
    const auto y = [&](double v) {
        return top + kPanel - (v - low) / (high - low) * kPanel;
    };
    fmt::format_to(std::back_inserter(svg),
                   "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
                   "stroke=\"#999\"/>\n",
                   kLeft, top, width, kPanel);
    fmt::format_to(std::back_inserter(svg),
                   "<text x=\"{}\" y=\"{}\" font-size=\"12\">axis {} {}</text>\n", kLeft, top - 4,
                   axis.axis, panel.title);
    fmt::format_to(std::back_inserter(svg),
                   "<text x=\"{}\" y=\"{}\" font-size=\"10\" text-anchor=\"end\">{:g}</text>\n"
                   "<text x=\"{}\" y=\"{}\" font-size=\"10\" text-anchor=\"end\">{:g}</text>\n",
                   kLeft - 4, top + 10, high, kLeft - 4, top + kPanel, low);
    const std::size_t step = std::max<std::size_t>(1, panel.values->size() / kMostPoints);
    svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.2\" points=\"",
                       panel.colour);
    for (std::size_t i = 0; i < panel.values->size(); i += step) {
        fmt::format_to(std::back_inserter(svg), "{:.1f},{:.1f} ", x(axis.time_s[i]),
                       y((*panel.values)[i]));
    }
    svg += "\"/>\n";
}

void draw_states(std::string& svg, const AxisSeries& axis, double top, double t0, double t1) {
    const double width = kWidth - kLeft - kRight;
    const auto x = [&](double t) {
        return kLeft + (t - t0) / (t1 - t0) * width;
    };
    std::size_t begin = 0;
    for (std::size_t i = 1; i <= axis.state.size(); ++i) {
        if (i < axis.state.size() && axis.state[i] == axis.state[begin]) {
            continue;
        }
        const double end = i < axis.state.size() ? axis.time_s[i] : t1;
        fmt::format_to(std::back_inserter(svg),
                       "<rect x=\"{:.1f}\" y=\"{}\" width=\"{:.1f}\" height=\"{}\" fill=\"{}\">"
                       "<title>{}</title></rect>\n",
                       x(axis.time_s[begin]), top, std::max(0.5, x(end) - x(axis.time_s[begin])),
                       kBand, colour_of(axis.state[begin]), axis.state[begin]);
        begin = i;
    }
}

} // namespace

core::Result<std::vector<AxisSeries>> read_axis_trace(std::istream& in, std::string_view name) {
    std::string line;
    if (!std::getline(in, line)) {
        return core::Error{fmt::format("{}: empty: not an axis trace", name)};
    }
    const auto header = split(line);
    const auto column = [&](std::string_view wanted) -> std::ptrdiff_t {
        const auto it = std::find(header.begin(), header.end(), wanted);
        return it == header.end() ? -1 : it - header.begin();
    };
    const std::ptrdiff_t time = column("time_s"), axis = column("axis"),
                         position = column("actual_position"), velocity = column("actual_velocity"),
                         current = column("current_mA"), state = column("plcopen_state");
    if (time < 0 || axis < 0 || position < 0 || velocity < 0 || current < 0) {
        return core::Error{
            fmt::format("{}:1: not an axis trace: the header lacks time_s, axis, actual_position, "
                        "actual_velocity or current_mA (eposp run --trace writes one)",
                        name)};
    }
    std::vector<AxisSeries> axes;
    std::map<int, std::size_t> index_of;
    for (int number = 2; std::getline(in, line); ++number) {
        if (line.empty()) {
            continue;
        }
        const auto cells = split(line);
        double t = 0, a = 0, p = 0, v = 0, c = 0;
        if (cells.size() != header.size() || !number_at(cells, time, t) ||
            !number_at(cells, axis, a) || !number_at(cells, position, p) ||
            !number_at(cells, velocity, v) || !number_at(cells, current, c) || a < 0 || a > 255) {
            return core::Error{fmt::format("{}:{}: not a row of the axis trace", name, number)};
        }
        const auto [it, added] = index_of.try_emplace(static_cast<int>(a), axes.size());
        if (added) {
            axes.emplace_back().axis = static_cast<std::uint8_t>(a);
        }
        AxisSeries& series = axes[it->second];
        if (!series.time_s.empty() && t < series.time_s.back()) {
            return core::Error{fmt::format("{}:{}: time goes backwards", name, number)};
        }
        series.time_s.push_back(t);
        series.position.push_back(p);
        series.velocity.push_back(v);
        series.current.push_back(c);
        series.state.emplace_back(state >= 0 ? cells[static_cast<std::size_t>(state)] : "");
    }
    if (axes.empty()) {
        return core::Error{fmt::format("{}: the trace has no rows", name)};
    }
    return axes;
}

std::string plot_svg(const std::vector<AxisSeries>& axes) {
    double t0 = axes.front().time_s.front();
    double t1 = t0;
    for (const AxisSeries& axis : axes) {
        t0 = std::min(t0, axis.time_s.front());
        t1 = std::max(t1, axis.time_s.back());
    }
    if (t1 - t0 < 1e-9) {
        t1 = t0 + 1;
    }
    const double per_axis = 3 * (kPanel + kGap) + kBand;
    const double height = kGap + static_cast<double>(axes.size()) * per_axis + 20;
    std::string svg = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
        "font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        kWidth, height);
    double top = kGap;
    for (const AxisSeries& axis : axes) {
        draw_panel(svg, axis, {"actual position (qc)", &axis.position, "#1f4e79"}, top, t0, t1);
        top += kPanel;
        if (!axis.state.empty() && !axis.state.front().empty()) {
            draw_states(svg, axis, top + 2, t0, t1);
        }
        top += kBand + kGap;
        draw_panel(svg, axis, {"actual velocity (rpm)", &axis.velocity, "#38761d"}, top, t0, t1);
        top += kPanel + kGap;
        draw_panel(svg, axis, {"current (mA)", &axis.current, "#990000"}, top, t0, t1);
        top += kPanel + kGap;
    }
    fmt::format_to(std::back_inserter(svg),
                   "<text x=\"{}\" y=\"{}\" font-size=\"11\" text-anchor=\"middle\">time (s), "
                   "{:g} to {:g}</text>\n</svg>\n",
                   kLeft + (kWidth - kLeft - kRight) / 2, top - kGap + 14, t0, t1);
    return svg;
}

} // namespace eposp::device
