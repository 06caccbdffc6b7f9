// main() of every benchmark program: the same memory policy as the apps (sylva-cli, sylva),
// so that the benchmarks measure what a user's repeated generation costs.
#include <benchmark/benchmark.h>

#include "engine/util/memorypolicy.h"

int main(int argc, char** argv) {
    sylva::keepFreedMemory();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
