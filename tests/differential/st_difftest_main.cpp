// st_difftest: the differential test as a long-running job. Generates programs from consecutive
// seeds, runs each on every executor, and prints each mismatch with its seed and reduced program
// and, every few seconds, how many programs it has checked per second.
//
//   st_difftest --seeds N [--from S]     N programs from seed S (default 1)
//   st_difftest --minutes M [--from S]   as many as fit in M minutes
//   st_difftest --print SEED             the program of one seed, to reproduce by hand
//   st_difftest --file PROGRAM.st        one program (a reduced one, edited) on every executor
//   options: --scans K (4), --no-reduce, --ties (real-to-integer conversions of ties),
//            --without FEATURE (reals strings arrays structs loops case in-out
//            huge-case-labels string-max-min-limit constants times; repeatable)

#include "eposp/differential/differential_check.hpp"
#include "eposp/differential/executors.hpp"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>

namespace {

using namespace eposp::differential;

struct Arguments {
    std::uint64_t from = 1;
    std::uint64_t seeds = 0;
    double minutes = 0;
    std::optional<std::uint64_t> print;
    std::string file;
    int scans = 4;
    bool reduce = true;
    GeneratorOptions options;
};

/// Turns a feature of the generator off by its name in --without.
bool switch_off(GeneratorOptions& options, const std::string& feature) {
    const std::pair<const char*, bool GeneratorOptions::*> features[] = {
        {"reals", &GeneratorOptions::reals},
        {"strings", &GeneratorOptions::strings},
        {"arrays", &GeneratorOptions::arrays},
        {"structs", &GeneratorOptions::structs},
        {"loops", &GeneratorOptions::loops},
        {"case", &GeneratorOptions::case_statements},
        {"in-out", &GeneratorOptions::in_out},
        {"huge-case-labels", &GeneratorOptions::huge_case_labels},
        {"string-max-min-limit", &GeneratorOptions::string_max_min_limit},
        {"constants", &GeneratorOptions::constants},
        {"times", &GeneratorOptions::times},
    };
    for (const auto& [name, member] : features) {
        if (feature == name) {
            options.*member = false;
            return true;
        }
    }
    return false;
}

/// Programs an executor refused (the reference evaluator does not support everything): a
/// comparison that silently lost an executor must not read as agreement.
struct Refusals {
    std::map<std::string, std::uint64_t> count;
    std::map<std::string, std::string> example;
};

void count_refusals(const Verdict& verdict, Refusals& refusals) {
    for (std::size_t i = 0; i < verdict.classes.size(); ++i) {
        if (verdict.classes[i] == -1) {
            const std::string& name = verdict.names[i];
            if (refusals.count[name]++ == 0) {
                const std::string& errors = verdict.executions[i].errors;
                refusals.example[name] = errors.substr(0, errors.find('\n'));
            }
        }
    }
}

std::optional<Arguments> parse(int argc, char** argv) {
    Arguments arguments;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        const bool has_value = i + 1 < argc;
        if (flag == "--seeds" && has_value) {
            arguments.seeds = std::stoull(argv[++i]);
        } else if (flag == "--from" && has_value) {
            arguments.from = std::stoull(argv[++i]);
        } else if (flag == "--minutes" && has_value) {
            arguments.minutes = std::stod(argv[++i]);
        } else if (flag == "--print" && has_value) {
            arguments.print = std::stoull(argv[++i]);
        } else if (flag == "--file" && has_value) {
            arguments.file = argv[++i];
        } else if (flag == "--scans" && has_value) {
            arguments.scans = std::stoi(argv[++i]);
        } else if (flag == "--no-reduce") {
            arguments.reduce = false;
        } else if (flag == "--ties") {
            arguments.options.real_ties = true;
        } else if (flag == "--without" && has_value) {
            if (!switch_off(arguments.options, argv[++i])) {
                return std::nullopt;
            }
        } else {
            return std::nullopt;
        }
    }
    if (arguments.seeds == 0 && arguments.minutes <= 0 && !arguments.print &&
        arguments.file.empty()) {
        return std::nullopt;
    }
    return arguments;
}

} // namespace

int main(int argc, char** argv) {
    const auto arguments = parse(argc, argv);
    if (!arguments) {
        std::cerr
            << "usage: st_difftest (--seeds N | --minutes M | --print SEED | --file PATH) [--from "
               "S] "
               "[--scans K] [--no-reduce] [--ties] [--without FEATURE]...\n";
        return 2;
    }
    if (arguments->print) {
        std::mt19937_64 random(*arguments->print);
        std::cout << render(generate_program(random, arguments->options).block);
        return 0;
    }
    auto executors = all_executors();
    if (!arguments->file.empty()) {
        std::ifstream in(arguments->file);
        std::ostringstream source;
        source << in.rdbuf();
        const Verdict verdict = compare(executors.pointers(), source.str(), arguments->scans);
        std::cout << verdict.describe();
        return verdict.outcome == Verdict::Outcome::Agree ? 0 : 1;
    }
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    Refusals refusals;
    double last_report = 0;
    std::uint64_t checked = 0;
    std::uint64_t found = 0;
    for (std::uint64_t seed = arguments->from;; ++seed) {
        if (arguments->seeds > 0 ? checked >= arguments->seeds
                                 : elapsed() >= arguments->minutes * 60) {
            break;
        }
        const auto finding = check_seed(seed, arguments->options, executors.pointers(),
                                        arguments->scans, arguments->reduce);
        if (!finding.agree()) {
            ++found;
            std::cout << describe(finding) << std::endl;
        }
        count_refusals(finding.verdict, refusals);
        ++checked;
        if (elapsed() - last_report >= 10) {
            last_report = elapsed();
            std::printf("%llu programs (seeds %llu..%llu), %.1f programs/s, %llu mismatches\n",
                        static_cast<unsigned long long>(checked),
                        static_cast<unsigned long long>(arguments->from),
                        static_cast<unsigned long long>(seed),
                        static_cast<double>(checked) / elapsed(),
                        static_cast<unsigned long long>(found));
            std::fflush(stdout);
        }
    }
    std::printf("done: %llu programs in %.0f s (%.1f programs/s), %llu mismatches; executors:",
                static_cast<unsigned long long>(checked), elapsed(),
                static_cast<double>(checked) / elapsed(), static_cast<unsigned long long>(found));
    for (const Executor* executor : executors.pointers()) {
        std::printf(" %s", executor->name().c_str());
    }
    std::printf("\n");
    for (const auto& [name, count] : refusals.count) {
        std::printf("%s refused %llu of %llu programs, e.g. %s\n", name.c_str(),
                    static_cast<unsigned long long>(count),
                    static_cast<unsigned long long>(checked), refusals.example[name].c_str());
    }
    return found == 0 ? 0 : 1;
}
