#pragma once
// Native benchmark harness (docs/benchmarks.md): each task runs R >= 5 repetitions and
// prints one JSON line with the minimum and median time per work unit and a checksum.
// Benchmark files register themselves with WINGSPLINE_BENCH(name) { ... }.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace wingspline::bench {

struct Context {
    std::vector<std::string> filters; // task-name prefixes from the command line; empty = all
    bool wants(const std::string& task) const {
        if (filters.empty()) return true;
        for (const auto& f : filters)
            if (task.rfind(f, 0) == 0) return true;
        return false;
    }
};

using Group = std::function<void(const Context&)>;
std::vector<std::pair<std::string, Group>>& groups();

struct Registrar {
    Registrar(const char* name, Group g) { groups().emplace_back(name, std::move(g)); }
};

inline double now_seconds() {
    using clock = std::chrono::steady_clock;
    return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// Times `repetitions` runs of body(); returns the seconds of each run.
template <class F> std::vector<double> time_runs(int repetitions, F&& body) {
    std::vector<double> seconds;
    for (int r = 0; r < repetitions; ++r) {
        const double t0 = now_seconds();
        body();
        seconds.push_back(now_seconds() - t0);
    }
    return seconds;
}

// Prints {"task", "build":"native", "input", "n", "ns_per_unit_min", "ns_per_unit_median",
// "checksum", ...extra}. `extra_json` is either empty or starts with a comma.
inline void report(const std::string& task, const std::string& input, double n,
                   std::vector<double> seconds, double checksum, const std::string& extra_json = "",
                   const std::string& unit = "ns") {
    std::sort(seconds.begin(), seconds.end());
    const double scale = unit == "ns" ? 1e9 : 1.0;
    const double min = seconds.front() * scale / n;
    const double median = seconds[seconds.size() / 2] * scale / n;
    std::printf("{\"task\":\"%s\",\"build\":\"native\",\"input\":\"%s\",\"n\":%.0f,"
                "\"repetitions\":%zu,\"ns_per_unit_min\":%.6g,\"ns_per_unit_median\":%.6g,"
                "\"checksum\":%.17g%s}\n",
                task.c_str(), input.c_str(), n, seconds.size(), min, median, checksum, extra_json.c_str());
    std::fflush(stdout);
}

} // namespace wingspline::bench

#define WINGSPLINE_BENCH_CAT2(a, b) a##b
#define WINGSPLINE_BENCH_CAT(a, b) WINGSPLINE_BENCH_CAT2(a, b)
#define WINGSPLINE_BENCH(name)                                                                  \
    static void WINGSPLINE_BENCH_CAT(bench_group_, name)(const ::wingspline::bench::Context&);  \
    static ::wingspline::bench::Registrar WINGSPLINE_BENCH_CAT(bench_registrar_, name)(          \
        #name, &WINGSPLINE_BENCH_CAT(bench_group_, name));                                      \
    static void WINGSPLINE_BENCH_CAT(bench_group_, name)(const ::wingspline::bench::Context& ctx)
