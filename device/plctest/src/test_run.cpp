#include "eposp/plctest/test_run.hpp"

#include <algorithm>
#include <atomic>
#include <fnmatch.h>
#include <numeric>
#include <optional>
#include <random>
#include <thread>

namespace eposp::plctest {
namespace {

std::vector<std::string> split(std::string_view list) {
    std::vector<std::string> globs;
    while (!list.empty()) {
        const std::size_t end = std::min(list.find(':'), list.size());
        if (end > 0) {
            globs.emplace_back(list.substr(0, end));
        }
        list.remove_prefix(std::min(end + 1, list.size()));
    }
    return globs;
}

bool matches(const std::string& glob, const std::string& name) {
    return fnmatch(glob.c_str(), name.c_str(), 0) == 0;
}

} // namespace

TestFilter::TestFilter(std::string_view filter) {
    const std::size_t minus = filter.find('-');
    positive_ = split(filter.substr(0, minus));
    if (minus != std::string_view::npos) {
        negative_ = split(filter.substr(minus + 1));
    }
}

bool TestFilter::selects(std::string_view suite, std::string_view test) const {
    const std::string name = std::string(suite) + "." + std::string(test);
    const auto match = [&name](const std::string& glob) {
        return matches(glob, name);
    };
    return (positive_.empty() || std::ranges::any_of(positive_, match)) &&
           std::ranges::none_of(negative_, match);
}

bool TestFilter::may_select(std::string_view suite) const {
    // A glob with a '.' names the suite before it; one without may match any test name.
    return positive_.empty() || std::ranges::any_of(positive_, [suite](const std::string& glob) {
               const std::size_t dot = glob.find('.');
               return dot == std::string::npos || matches(glob.substr(0, dot), std::string(suite));
           });
}

core::Result<TestRun> run_tests(const TestRunOptions& options) {
    auto sources = discover_suites(options.paths, options.observe_diagnostics);
    if (!sources) {
        return core::Error{sources.error()};
    }
    TestRun run{.sources = std::move(*sources), .suites = {}, .coverage = {}};
    std::vector<const Suite*> suites;
    for (const Suite& suite : run.sources.suites) {
        if (options.filter.may_select(suite.name)) {
            suites.push_back(&suite);
        }
    }
    RunSettings settings = options.settings;
    settings.selected = [&options](std::string_view suite, std::string_view test) {
        return options.filter.selects(suite, test);
    };
    // Each suite's machine: its network attribute's, else --network's, else the one-axis
    // device; compiled one after the other (the parser's caches are shared between instances).
    std::vector<RunSettings> suite_settings(suites.size(), settings);
    std::vector<std::optional<core::Result<vm::Image>>> images;
    for (std::size_t i = 0; i < suites.size(); ++i) {
        if (const auto& path = suites[i]->network) {
            auto network = device::load_network_file(*path);
            if (!network) {
                images.emplace_back(core::Error{"its network attribute: " + network.error()});
                continue;
            }
            suite_settings[i].network = std::move(*network);
        }
        const auto& network = suite_settings[i].network;
        images.emplace_back(build_suite(run.sources, *suites[i],
                                        test_cycle(network.value_or(default_network())),
                                        settings.coverage, options.observe_diagnostics));
    }
    std::vector<std::size_t> order(suites.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (options.seed) {
        std::mt19937_64 random(*options.seed);
        std::ranges::shuffle(order, random);
    }
    std::vector<std::optional<SuiteRun>> runs(suites.size());
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t n = next++; n < suites.size(); n = next++) {
            const std::size_t i = order[n];
            runs[i] = run_suite(run.sources, *suites[i], std::move(*images[i]), suite_settings[i]);
        }
    };
    std::vector<std::jthread> workers;
    const std::size_t threads =
        std::max<std::size_t>(1, std::min<std::size_t>(options.jobs, suites.size()));
    for (std::size_t t = 1; t < threads; ++t) {
        workers.emplace_back(work);
    }
    work();
    workers.clear(); // joins
    for (std::optional<SuiteRun>& suite_run : runs) {
        // A suite without a selected test is not reported.
        if (!suite_run->result.tests.empty() || suite_run->result.error) {
            run.suites.push_back(std::move(suite_run->result));
        }
        run.coverage.merge(suite_run->coverage);
    }
    // Coverage of the user's POUs only: not of the harness, nor of the standard FBs.
    std::erase_if(run.coverage.pous,
                  [&run](const auto& pou) { return run.sources.file_of(pou.first).empty(); });
    return run;
}

} // namespace eposp::plctest
