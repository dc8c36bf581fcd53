// The standard function blocks, from IEC 61131-3 ed. 3 itself (tables 43-46 and the timing
// diagrams of figure 15), not from the project's library source: bistables, edge detection,
// counters and timers. Hidden state lives in members named with a `$`, which no ST name has.

#include "evaluator.hpp"

namespace eposp::reference {

using E = ast::ElementaryType;

namespace {

class Block {
public:
    Block(Value& instance, const sema::Type& boolean, const sema::Type& time)
        : instance_(instance), boolean_(boolean), time_(time) {}

    Value& at(const char* name) {
        Value* member = instance_.member(name);
        if (member == nullptr) {
            throw Unsupported(std::string("a standard FB without ") + name);
        }
        return *member;
    }
    bool get(const char* name) { return at(name).bits != 0; }
    void set(const char* name, bool value) { at(name) = integer(boolean_, value ? 1 : 0); }
    std::int64_t time(const char* name) { return at(name).as_signed(); }
    void set_time(const char* name, std::int64_t ns) {
        at(name) = integer(time_, static_cast<std::uint64_t>(ns));
    }
    /// Hidden state: a previous input, a start time.
    Value& state(const char* name, const sema::Type& type) {
        if (Value* member = instance_.member(name)) {
            return *member;
        }
        instance_.names.emplace_back(name);
        instance_.elements.push_back(integer(type, 0));
        return instance_.elements.back();
    }
    bool previous(const char* name, bool now) {
        Value& memory = state(name, boolean_);
        const bool before = memory.bits != 0;
        memory.bits = now ? 1 : 0;
        return before;
    }

private:
    Value& instance_;
    const sema::Type& boolean_;
    const sema::Type& time_;
};

} // namespace

void Evaluator::standard_function_block(const std::string& name, Value& instance) {
    const sema::Type& boolean = elementary(E::Bool);
    const sema::Type& time = elementary(E::Time);
    Block fb(instance, boolean, time);
    if (name == "SR") { // table 43: set dominant
        fb.set("Q1", fb.get("S1") || (!fb.get("R") && fb.get("Q1")));
        return;
    }
    if (name == "RS") { // reset dominant
        fb.set("Q1", !fb.get("R1") && (fb.get("S") || fb.get("Q1")));
        return;
    }
    if (name == "R_TRIG") { // table 44
        const bool clk = fb.get("CLK");
        const bool before = fb.previous("$M", clk);
        fb.set("Q", clk && !before);
        return;
    }
    if (name == "F_TRIG") {
        // The project's choice (stdlib): no falling edge on the first call, so the previous
        // CLK starts FALSE as for R_TRIG.
        const bool clk = fb.get("CLK");
        const bool before = fb.previous("$M", clk);
        fb.set("Q", !clk && before);
        return;
    }
    if (name.starts_with("CTU") || name.starts_with("CTD")) { // table 45
        const Value& cv = fb.at("CV");
        const sema::Type& type = *cv.type;
        const auto range = *ast::integer_range(type.elementary);
        const bool is_signed = signed_type(type);
        const auto below_max = [&](const Value& v) {
            return is_signed ? v.as_signed() < static_cast<std::int64_t>(range.max)
                             : v.bits < range.max;
        };
        const auto above_min = [&](const Value& v) {
            return is_signed ? v.as_signed() > range.min : v.bits > 0;
        };
        const bool up_down = name.starts_with("CTUD");
        const bool up = !name.starts_with("CTD");
        const bool down = up_down || !up;
        // Rising edges of CU and CD (the standard declares them R_EDGE).
        const auto edge = [&](bool present, const char* input, const char* memory) {
            if (!present) {
                return false;
            }
            const bool now = fb.get(input);
            const bool before = fb.previous(memory, now);
            return now && !before;
        };
        const bool cu = edge(up, "CU", "$MU");
        const bool cd = edge(down, "CD", "$MD");
        const Value pv = fb.at("PV");
        Value next = fb.at("CV");
        if (up && fb.get("R")) {
            next = integer(type, 0);
        } else if (down && fb.get("LD")) {
            next = pv;
        } else if (!(cu && cd)) {
            if (cu && below_max(next)) {
                next = integer(type, next.bits + 1);
            } else if (cd && above_min(next)) {
                next = integer(type, next.bits - 1);
            }
        }
        fb.at("CV") = next;
        const bool at_least_pv = order(next, pv) >= 0;
        const bool at_most_zero = is_signed ? next.as_signed() <= 0 : next.bits == 0;
        if (up_down) {
            fb.set("QU", at_least_pv);
            fb.set("QD", at_most_zero);
        } else {
            fb.set("Q", up ? at_least_pv : at_most_zero);
        }
        return;
    }
    const bool in = fb.get("IN");
    const std::int64_t pt = fb.time("PT");
    // All hidden members exist before any is held by reference (adding one moves the others).
    for (const char* hidden : {"$RUNNING", "$M"}) {
        fb.state(hidden, boolean);
    }
    fb.state("$START", time);
    Value& running = fb.state("$RUNNING", boolean);
    Value& start = fb.state("$START", time);
    if (name == "TP") {
        // Figure 15 a): a rising IN starts a pulse of PT that nothing stops; after it ET holds
        // PT while IN stays TRUE and is 0 once IN is FALSE, in the same call.
        const bool before = fb.previous("$M", in);
        const bool rising = in && !before;
        if (running.bits == 0 && rising) {
            running.bits = 1;
            start = integer(time, static_cast<std::uint64_t>(now_ns_));
        }
        if (running.bits != 0) {
            const std::int64_t et = now_ns_ - start.as_signed();
            if (et >= pt) {
                running.bits = 0;
                fb.set("Q", false);
                fb.set_time("ET", in ? pt : 0);
            } else {
                fb.set("Q", true);
                fb.set_time("ET", et);
            }
        } else if (!in) {
            fb.set_time("ET", 0);
        }
        return;
    }
    if (name == "TON") { // figure 15 b)
        if (!in) {
            running.bits = 0;
            fb.set("Q", false);
            fb.set_time("ET", 0);
            return;
        }
        if (running.bits == 0) {
            running.bits = 1;
            start = integer(time, static_cast<std::uint64_t>(now_ns_));
        }
        const std::int64_t et = now_ns_ - start.as_signed();
        fb.set("Q", et >= pt);
        fb.set_time("ET", et >= pt ? pt : et);
        return;
    }
    if (name == "TOF") { // figure 15 c)
        if (in) {
            running.bits = 0;
            fb.set("Q", true);
            fb.set_time("ET", 0);
            return;
        }
        if (!fb.get("Q")) {
            return; // ET holds
        }
        if (running.bits == 0) {
            running.bits = 1;
            start = integer(time, static_cast<std::uint64_t>(now_ns_));
        }
        const std::int64_t et = now_ns_ - start.as_signed();
        if (et >= pt) {
            running.bits = 0;
            fb.set("Q", false);
            fb.set_time("ET", pt);
        } else {
            fb.set_time("ET", et);
        }
        return;
    }
    throw Unsupported("the standard function block " + name);
}

} // namespace eposp::reference
