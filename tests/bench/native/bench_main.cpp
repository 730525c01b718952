// Runs every registered benchmark group; arguments are task-name prefixes to run.
#include "bench.h"

namespace wingspline::bench {
std::vector<std::pair<std::string, Group>>& groups() {
    static std::vector<std::pair<std::string, Group>> all;
    return all;
}
} // namespace wingspline::bench

int main(int argc, char** argv) {
    wingspline::bench::Context ctx;
    for (int i = 1; i < argc; ++i) ctx.filters.emplace_back(argv[i]);
    for (auto& [name, group] : wingspline::bench::groups()) group(ctx);
    return 0;
}
