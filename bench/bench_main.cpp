// The main() of every benchmark program. Each program defines register_benchmarks(), which builds its
// shapes and registers one benchmark per (shape, implementation, size) at run time — the shapes are
// computed, so BENCHMARK() macros at namespace scope would not do.
#include <benchmark/benchmark.h>

namespace ratbez::bench {
void register_benchmarks();
}

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    ratbez::bench::register_benchmarks();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
