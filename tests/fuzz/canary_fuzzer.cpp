// A harness that crashes on the input "crash": the fuzz_runner_detects_crash test checks that
// run-fuzzer.sh fails when a corpus input crashes, so a broken runner cannot pass silently.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 5 && std::memcmp(data, "crash", 5) == 0) std::abort();
    return 0;
}
