#include "eposp/core/event_loop.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <gtest/gtest.h>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace eposp::core {
namespace {

using namespace std::chrono_literals;

TimePoint at_ns(std::int64_t ns) {
    return TimePoint{Duration{ns}};
}

TEST(EventLoop, VirtualClockJumpsToEachEventAndThenToTheEnd) {
    EventLoop loop;
    std::vector<TimePoint> seen;
    loop.after(5ms, [&] { seen.push_back(loop.now()); });
    loop.after(1ms, [&] { seen.push_back(loop.now()); });
    EXPECT_EQ(loop.run_for(10ms), 2U);
    EXPECT_EQ(seen, (std::vector{TimePoint{1ms}, TimePoint{5ms}}));
    EXPECT_EQ(loop.now(), TimePoint{10ms});
}

TEST(EventLoop, EventsAtTheSameInstantRunInSchedulingOrder) {
    EventLoop loop;
    std::string order;
    loop.at(at_ns(100), [&] { order += 'a'; });
    loop.at(at_ns(100), [&] { order += 'b'; });
    loop.at(at_ns(50), [&] {
        order += 'x';
        loop.at(at_ns(100), [&] { order += 'c'; }); // scheduled later, so it runs later
    });
    loop.run();
    EXPECT_EQ(order, "xabc");
}

// The queue is a heap: whatever its shape, events run by time and, at the same time, in the
// order they were scheduled. Thousands of events on a few instants, a third cancelled before
// they run, against a stable sort of what was scheduled.
TEST(EventLoop, ManyPendingEventsRunByTimeThenInSchedulingOrder) {
    EventLoop loop;
    std::mt19937 random(7);
    std::uniform_int_distribution<std::int64_t> instant(0, 40);
    struct Scheduled {
        std::int64_t when;
        int number;
        bool cancelled;
    };
    std::vector<Scheduled> scheduled;
    std::vector<TimerId> ids;
    std::vector<int> ran;
    for (int number = 0; number < 3000; ++number) {
        const std::int64_t when = instant(random);
        scheduled.push_back({when, number, false});
        ids.push_back(loop.at(at_ns(when), [&ran, number] { ran.push_back(number); }));
    }
    for (std::size_t i = 0; i < scheduled.size(); i += 3) {
        EXPECT_TRUE(loop.cancel(ids[i]));
        scheduled[i].cancelled = true;
    }
    std::stable_sort(scheduled.begin(), scheduled.end(),
                     [](const Scheduled& a, const Scheduled& b) { return a.when < b.when; });
    std::vector<int> expected;
    for (const Scheduled& event : scheduled) {
        if (!event.cancelled) {
            expected.push_back(event.number);
        }
    }
    loop.run();
    EXPECT_EQ(ran, expected);
}

// An alarm runs where a timer scheduled at its arming would: by time, then in the order of
// scheduling and arming; arming it again moves it (the earlier arming does not run). Timers,
// alarms armed once or several times and cancelled timers on a few instants, against a stable
// sort of what was scheduled.
TEST(EventLoop, AlarmsRunAmongTimersInTheOrderTheyWereArmed) {
    EventLoop loop;
    std::mt19937 random(11);
    std::uniform_int_distribution<std::int64_t> instant(0, 40);
    std::uniform_int_distribution<int> kind(0, 3);
    struct Scheduled {
        std::int64_t when;
        int number;
        bool dropped;
    };
    std::vector<Scheduled> scheduled;
    std::vector<int> ran;
    std::vector<std::unique_ptr<Alarm>> alarms;
    std::vector<std::size_t> last_arming; // of each alarm, in `scheduled`
    for (int number = 0; number < 3000; ++number) {
        const std::int64_t when = instant(random);
        const int what = kind(random);
        if (what == 0 || alarms.empty()) {
            const int alarm_number = -static_cast<int>(alarms.size()) - 1;
            alarms.push_back(std::make_unique<Alarm>(
                loop, [&ran, alarm_number] { ran.push_back(alarm_number); }));
            last_arming.push_back(scheduled.size());
            scheduled.push_back({when, alarm_number, false});
            alarms.back()->arm(at_ns(when));
        } else if (what == 1) {
            const std::size_t alarm = static_cast<std::size_t>(number) % alarms.size();
            scheduled[last_arming[alarm]].dropped = true;
            last_arming[alarm] = scheduled.size();
            scheduled.push_back({when, -static_cast<int>(alarm) - 1, false});
            alarms[alarm]->arm(at_ns(when));
        } else {
            const TimerId id = loop.at(at_ns(when), [&ran, number] { ran.push_back(number); });
            scheduled.push_back({when, number, what == 3});
            if (what == 3) {
                EXPECT_TRUE(loop.cancel(id));
            }
        }
    }
    EXPECT_EQ(loop.pending_count(), static_cast<std::size_t>(std::count_if(
                                        scheduled.begin(), scheduled.end(),
                                        [](const Scheduled& event) { return !event.dropped; })));
    std::stable_sort(scheduled.begin(), scheduled.end(),
                     [](const Scheduled& a, const Scheduled& b) { return a.when < b.when; });
    std::vector<int> expected;
    for (const Scheduled& event : scheduled) {
        if (!event.dropped) {
            expected.push_back(event.number);
        }
    }
    loop.run();
    EXPECT_EQ(ran, expected);
    EXPECT_EQ(loop.pending_count(), 0U);
}

// Armed until its callback returns, as a timer is pending; armed again from there it runs again;
// disarmed it does not run; it may be destroyed from its own callback.
TEST(EventLoop, AnAlarmIsArmedUntilItsCallbackReturns) {
    EventLoop loop;
    std::vector<std::int64_t> ran;
    std::unique_ptr<Alarm> alarm;
    alarm = std::make_unique<Alarm>(loop, [&] {
        ran.push_back(loop.now().time_since_epoch().count());
        EXPECT_TRUE(alarm->armed());
        if (ran.size() < 3) {
            alarm->arm(loop.now() + std::chrono::nanoseconds(5));
        } else {
            alarm.reset();
        }
    });
    EXPECT_FALSE(alarm->armed());
    alarm->arm(at_ns(10));
    EXPECT_TRUE(alarm->armed());
    EXPECT_EQ(loop.pending_count(), 1U);
    loop.run();
    EXPECT_EQ(ran, (std::vector<std::int64_t>{10, 15, 20}));
    EXPECT_EQ(alarm, nullptr);

    Alarm disarmed(loop, [&] { ran.push_back(-1); });
    disarmed.arm(at_ns(30));
    disarmed.disarm();
    EXPECT_FALSE(disarmed.armed());
    EXPECT_EQ(loop.pending_count(), 0U);
    Alarm once(loop, [&] { ran.push_back(loop.now().time_since_epoch().count()); });
    once.arm(at_ns(40));
    loop.run();
    EXPECT_FALSE(once.armed());
    EXPECT_EQ(ran, (std::vector<std::int64_t>{10, 15, 20, 40}));
}

TEST(EventLoop, NanosecondResolution) {
    EventLoop loop;
    TimePoint fired{};
    loop.at(at_ns(1), [&] { fired = loop.now(); });
    loop.run();
    EXPECT_EQ(fired, at_ns(1));
}

TEST(EventLoop, TimeInThePastRunsNowAndNeverGoesBackwards) {
    EventLoop loop;
    loop.run_for(10ms);
    TimePoint fired{};
    loop.at(TimePoint{1ms}, [&] { fired = loop.now(); });
    loop.run();
    EXPECT_EQ(fired, TimePoint{10ms});
}

TEST(EventLoop, CancelledTimerDoesNotRun) {
    EventLoop loop;
    bool ran = false;
    const TimerId id = loop.after(1ms, [&] { ran = true; });
    EXPECT_TRUE(loop.pending(id));
    EXPECT_TRUE(loop.cancel(id));
    EXPECT_FALSE(loop.cancel(id));
    loop.run();
    EXPECT_FALSE(ran);
    EXPECT_EQ(loop.pending_count(), 0U);
}

TEST(EventLoop, OneShotIsNoLongerPendingAfterItRan) {
    EventLoop loop;
    const TimerId id = loop.after(1ms, [] {});
    loop.run();
    EXPECT_FALSE(loop.pending(id));
    EXPECT_FALSE(loop.cancel(id));
}

TEST(EventLoop, PeriodicTimerCanCancelItselfFromItsCallback) {
    EventLoop loop;
    int runs = 0;
    TimerId id;
    id = loop.every(1ms, [&] {
        if (++runs == 3) {
            loop.cancel(id);
        }
    });
    loop.run_for(1s);
    EXPECT_EQ(runs, 3);
}

TEST(EventLoop, PeriodicTimerHasNoDriftOverAMillionPeriods) {
    EventLoop loop;
    // 333'333 ns is not a divisor of any larger unit: rounding anywhere would show.
    constexpr Duration kPeriod{333'333};
    std::int64_t runs = 0;
    bool on_schedule = true;
    loop.every(kPeriod, TimePoint{kPeriod}, [&] {
        ++runs;
        on_schedule = on_schedule && loop.now() == TimePoint{kPeriod * runs};
    });
    loop.run_until(TimePoint{kPeriod * 1'000'000});
    EXPECT_EQ(runs, 1'000'000);
    EXPECT_TRUE(on_schedule);
}

TEST(EventLoop, PeriodicTimerStaysOnScheduleWhenOtherEventsInterleave) {
    EventLoop loop;
    std::vector<TimePoint> ticks;
    loop.every(1ms, [&] { ticks.push_back(loop.now()); });
    loop.every(Duration{700'001}, [] {});
    loop.run_for(5ms);
    EXPECT_EQ(ticks, (std::vector{TimePoint{1ms}, TimePoint{2ms}, TimePoint{3ms}, TimePoint{4ms},
                                  TimePoint{5ms}}));
}

TEST(EventLoop, EveryRejectsANonPositivePeriod) {
    EventLoop loop;
    EXPECT_THROW(loop.every(Duration::zero(), [] {}), std::invalid_argument);
}

TEST(EventLoop, StopReturnsAfterTheCurrentCallback) {
    EventLoop loop;
    int runs = 0;
    loop.every(1ms, [&] {
        if (++runs == 4) {
            loop.stop();
        }
    });
    loop.run_for(1s);
    EXPECT_EQ(runs, 4);
    EXPECT_EQ(loop.now(), TimePoint{4ms});
    loop.run_for(2ms); // a new run starts afresh
    EXPECT_EQ(runs, 6);
}

// The virtual bus arbitrates at once instead of posting when nothing could come in between.
TEST(EventLoop, APostedCallIsNextInLineOnlyWhenNothingElseIsDueNow) {
    EventLoop loop;
    std::vector<bool> seen;
    loop.at(TimePoint{1ms}, [&] { seen.push_back(loop.next_in_line()); }); // the next is due now
    loop.at(TimePoint{1ms}, [&] {
        seen.push_back(loop.next_in_line());                     // the next is at 2 ms
        loop.post([&] { seen.push_back(loop.next_in_line()); }); // posted: due now
        seen.push_back(loop.next_in_line());
    });
    loop.at(TimePoint{2ms}, [&] {
        loop.stop();
        seen.push_back(loop.next_in_line()); // the loop returns first
    });
    loop.run();
    EXPECT_EQ(seen, (std::vector<bool>{false, true, false, true, false}));
}

// The virtual bus goes on to a frame's next instant in the same event when the loop would run
// that instant's event next: only when no other event is due by then, within the run.
TEST(EventLoop, ACallbackAdvancesOnlyWhenNothingElseIsDueByThen) {
    EventLoop loop;
    std::vector<bool> seen;
    std::vector<TimePoint> times;
    loop.at(TimePoint{1ms}, [&] {
        seen.push_back(loop.advance_to(TimePoint{3ms})); // an event is due at 3 ms
        seen.push_back(loop.advance_to(TimePoint{2ms}));
        times.push_back(loop.now());
        seen.push_back(loop.advance_to(TimePoint{2ms})); // now itself: nothing else is due
        loop.post([] {});
        seen.push_back(loop.advance_to(TimePoint{2ms} + 1ns)); // the posted call comes first
    });
    loop.at(TimePoint{3ms}, [&] {
        times.push_back(loop.now());
        seen.push_back(loop.advance_to(TimePoint{5ms})); // past the run's end
        seen.push_back(loop.advance_to(TimePoint{4ms})); // the run's end is inclusive
        times.push_back(loop.now());
        loop.stop();
        seen.push_back(loop.advance_to(TimePoint{4ms})); // the loop returns first
    });
    // Six callbacks run: the three scheduled and the three advances; none when it refuses.
    EXPECT_EQ(loop.run_until(TimePoint{4ms}), 6U);
    EXPECT_EQ(seen, (std::vector<bool>{false, true, true, false, false, true, false}));
    EXPECT_EQ(times, (std::vector<TimePoint>{TimePoint{2ms}, TimePoint{3ms}, TimePoint{4ms}}));
    EXPECT_FALSE(loop.advance_to(TimePoint{5ms})); // outside a callback
    EXPECT_EQ(loop.now(), TimePoint{4ms});
}

// A callback that runs the loop itself: its own run's end holds again afterwards, and it is
// still a callback that may go on in time.
TEST(EventLoop, AnInnerRunLeavesTheOuterRunsEnd) {
    EventLoop loop;
    std::vector<bool> seen;
    loop.at(TimePoint{1ms}, [&] {
        loop.run_until(TimePoint{1ms}); // nothing more is due: returns at once
        seen.push_back(loop.advance_to(TimePoint{2ms}));
        loop.post([] {});
        EXPECT_EQ(loop.run_until(TimePoint{2ms}), 1U); // runs the posted call
        seen.push_back(loop.advance_to(TimePoint{3ms}));
    });
    loop.run_until(TimePoint{4ms});
    EXPECT_EQ(seen, (std::vector<bool>{true, true}));
}

// A callback's exception leaves the inner run it was called from: the outer run's end holds
// again all the same.
TEST(EventLoop, AnInnerRunLeftByAnExceptionLeavesTheOuterRunsEnd) {
    EventLoop loop;
    std::vector<bool> seen;
    loop.at(TimePoint{1ms}, [&] {
        loop.post([] { throw std::runtime_error("a programming error"); });
        EXPECT_THROW(loop.run_until(TimePoint{2ms}), std::runtime_error);
        seen.push_back(loop.advance_to(TimePoint{5ms})); // past the outer run's end
        seen.push_back(loop.advance_to(TimePoint{3ms})); // past the inner run's end only
    });
    loop.run_until(TimePoint{4ms});
    EXPECT_EQ(seen, (std::vector<bool>{false, true}));
    EXPECT_EQ(loop.now(), TimePoint{4ms});
}

TEST(EventLoop, RunReturnsWhenNoEventIsLeft) {
    EventLoop loop;
    loop.after(3s, [] {});
    EXPECT_EQ(loop.run(), 1U);
    EXPECT_EQ(loop.now(), TimePoint{3s});
}

TEST(EventLoop, ScopedTimerCancelsOnDestruction) {
    EventLoop loop;
    bool ran = false;
    {
        ScopedTimer timer(loop, loop.after(1ms, [&] { ran = true; }));
        EXPECT_TRUE(timer.pending());
    }
    loop.run();
    EXPECT_FALSE(ran);
}

TEST(EventLoop, ScopedTimerMoveKeepsOneOwner) {
    EventLoop loop;
    int runs = 0;
    ScopedTimer outer;
    {
        ScopedTimer inner(loop, loop.every(1ms, [&] { ++runs; }));
        outer = std::move(inner);
    }
    loop.run_for(3ms);
    EXPECT_EQ(runs, 3);
    outer.cancel();
    loop.run_for(3ms);
    EXPECT_EQ(runs, 3);
}

// The queue keeps a run of events pushed one after another at one instant (periodic timers
// re-armed in turn, as the drives' control periods are) as one heap entry. Periodic timers on a
// shared and on their own phases whose callbacks schedule one-shots (now, at the next period,
// in between), cancel timers of the run and re-arm an alarm, against a plain model: the pending
// events in a list, the least (time, sequence) runs next, a periodic one is scheduled again after
// its callback.
TEST(EventLoop, EventsPushedInTurnAtOneInstantRunAsIfEachWereScheduledAlone) {
    constexpr std::int64_t kPeriod = 1000;
    constexpr int kTimers = 12;
    struct Model {
        struct Pending {
            std::int64_t when;
            std::uint64_t sequence;
            int number;
            std::int64_t period;
        };
        std::vector<Pending> pending;
        std::uint64_t next_sequence = 0;
        void schedule(std::int64_t when, int number, std::int64_t period) {
            pending.push_back({when, next_sequence++, number, period});
        }
        void cancel(int number) {
            std::erase_if(pending, [number](const Pending& p) { return p.number == number; });
        }
    };
    // What the callback of `number` does at its run `count`: the same in the loop and the model.
    const auto actions = [](int number, int count) {
        std::mt19937 random(static_cast<unsigned>(number * 7919 + count));
        return std::array<int, 3>{static_cast<int>(random() % 16), static_cast<int>(random() % 5),
                                  static_cast<int>(random() % kTimers)};
    };

    EventLoop loop;
    std::vector<std::pair<std::int64_t, int>> ran;
    std::vector<TimerId> ids(kTimers);
    std::vector<int> runs(kTimers + 1);
    int next_one_shot = 100;
    Alarm alarm(loop, [&] { ran.emplace_back(loop.now().time_since_epoch().count(), -1); });
    std::function<void(int)> run_timer = [&](int number) {
        const std::int64_t now = loop.now().time_since_epoch().count();
        ran.emplace_back(now, number);
        const auto [what, delay, victim] = actions(number, runs[number]++);
        const std::int64_t later[] = {0, kPeriod, kPeriod / 2, 1, 2 * kPeriod};
        if (what == 0) {
            const int one_shot = next_one_shot++;
            loop.at(at_ns(now + later[delay]), [&ran, &loop, one_shot] {
                ran.emplace_back(loop.now().time_since_epoch().count(), one_shot);
            });
        } else if (what == 1 && delay == 0 && victim != number) {
            loop.cancel(ids[static_cast<std::size_t>(victim)]);
        } else if (what == 2) {
            alarm.arm(at_ns(now + later[delay]));
        }
    };
    for (int number = 0; number < kTimers; ++number) {
        const std::int64_t first = number < 8 ? kPeriod : kPeriod + 250 * (number - 7);
        ids[static_cast<std::size_t>(number)] = loop.every(
            Duration{kPeriod}, at_ns(first), [&run_timer, number] { run_timer(number); });
    }
    loop.run_until(at_ns(40 * kPeriod));

    Model model;
    std::vector<std::pair<std::int64_t, int>> expected;
    std::vector<int> model_runs(kTimers + 1);
    int model_one_shot = 100;
    for (int number = 0; number < kTimers; ++number) {
        model.schedule(number < 8 ? kPeriod : kPeriod + 250 * (number - 7), number, kPeriod);
    }
    for (;;) {
        const auto next = std::min_element(
            model.pending.begin(), model.pending.end(), [](const auto& a, const auto& b) {
                return a.when != b.when ? a.when < b.when : a.sequence < b.sequence;
            });
        if (next == model.pending.end() || next->when > 40 * kPeriod) {
            break;
        }
        const Model::Pending event = *next;
        model.pending.erase(next);
        expected.emplace_back(event.when, event.number);
        if (event.number == -1 || event.number >= 100) {
            continue;
        }
        const auto [what, delay, victim] = actions(event.number, model_runs[event.number]++);
        const std::int64_t later[] = {0, kPeriod, kPeriod / 2, 1, 2 * kPeriod};
        if (what == 0) {
            model.schedule(event.when + later[delay], model_one_shot++, 0);
        } else if (what == 1 && delay == 0 && victim != event.number) {
            model.cancel(victim);
        } else if (what == 2) {
            model.cancel(-1); // armed again: moves
            model.schedule(event.when + later[delay], -1, 0);
        }
        if (event.period > 0) {
            model.schedule(event.when + event.period, event.number, event.period);
        }
    }
    EXPECT_GT(expected.size(), 300U);
    EXPECT_EQ(ran, expected);
}

// The latest event scheduled has run: what its callback schedules for the same instant starts a
// run of its own and runs once.
TEST(EventLoop, WhatTheLatestScheduledEventSchedulesForItsInstantRunsOnce) {
    EventLoop loop;
    std::string order;
    loop.at(at_ns(10), [&] {
        order += 'a';
        loop.post([&] {
            order += 'b';
            loop.post([&] { order += 'c'; });
        });
    });
    int rearmed = 0;
    Alarm alarm(loop, [&] {
        order += 'd';
        if (rearmed++ == 0) {
            alarm.arm(loop.now());
        }
    });
    loop.run();
    alarm.arm(loop.now() + 5ns);
    loop.run();
    EXPECT_EQ(order, "abcdd");
}

// A callback runs where it is stored: while it cancels itself and schedules a thousand timers
// (more slots, some of them reused), it and its captures stay; once it has returned it is
// destroyed.
TEST(EventLoop, ACallbackThatCancelsItselfAndSchedulesMoreLivesUntilItReturns) {
    EventLoop loop;
    bool destroyed = false;
    std::shared_ptr<void> token(nullptr, [&destroyed](void*) { destroyed = true; });
    TimerId self;
    int later = 0;
    std::optional<bool> destroyed_while_running;
    for (int i = 0; i < 10; ++i) {
        loop.cancel(loop.after(1ms, [] {})); // free slots to reuse
    }
    self = loop.every(1ms, [&, token] {
        loop.cancel(self);
        for (int i = 0; i < 1000; ++i) {
            loop.after(1ms, [&later] { ++later; });
        }
        destroyed_while_running = destroyed;
    });
    token.reset();
    EXPECT_FALSE(destroyed);
    loop.run();
    EXPECT_EQ(destroyed_while_running, false);
    EXPECT_EQ(later, 1000);
    EXPECT_TRUE(destroyed);
}

// A workload with timers scheduling, cancelling and re-arming each other, driven by a seeded
// generator: the trace of (time, event) must be identical on every run.
std::vector<std::pair<std::int64_t, int>> random_workload_trace(unsigned seed) {
    EventLoop loop;
    std::mt19937 random(seed);
    std::vector<std::pair<std::int64_t, int>> trace;
    std::vector<TimerId> ids;
    for (int i = 0; i < 200; ++i) {
        const Duration delay{std::uniform_int_distribution<std::int64_t>(0, 1'000'000)(random)};
        ids.push_back(loop.after(delay, [&, i] {
            trace.emplace_back(loop.now().time_since_epoch().count(), i);
            const Duration next{std::uniform_int_distribution<std::int64_t>(0, 50'000)(random)};
            if (i % 3 == 0) {
                loop.after(next, [&, i] {
                    trace.emplace_back(loop.now().time_since_epoch().count(), -i);
                });
            }
            if (i % 7 == 0 && !ids.empty()) {
                loop.cancel(ids[random() % ids.size()]);
            }
        }));
    }
    loop.every(Duration{12'345},
               [&] { trace.emplace_back(loop.now().time_since_epoch().count(), 1000); });
    loop.run_for(2ms);
    return trace;
}

TEST(EventLoop, VirtualRunsAreDeterministic) {
    const auto first = random_workload_trace(42);
    const auto second = random_workload_trace(42);
    EXPECT_GT(first.size(), 300U);
    EXPECT_EQ(first, second);
}

} // namespace
} // namespace eposp::core
