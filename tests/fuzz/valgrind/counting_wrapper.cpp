// Built only by scripts/fuzz-valgrind.sh, never by CMake: a libFuzzer entry point around a
// harness (compiled with -DLLVMFuzzerTestOneInput=sylvaHarnessInput) that saves every input after
// which valgrind's error count grew, so that each report of a run comes with the input that
// caused it (valgrind reports an invalid access when it happens, in any library; ASan only in
// instrumented code, or later).
#include <valgrind/memcheck.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int sylvaHarnessInput(const std::uint8_t* data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static unsigned seen = 0, saved = 0;
    static const char* folder = std::getenv("SYLVA_VALGRIND_FINDINGS");
    const int result = sylvaHarnessInput(data, size);
    const unsigned errors = VALGRIND_COUNT_ERRORS;
    if (errors != seen) {
        seen = errors;
        const std::string name =
            std::string(folder ? folder : ".") + "/valgrind-error-" + std::to_string(++saved);
        if (std::FILE* f = std::fopen(name.c_str(), "wb")) {
            std::fwrite(data, 1, size, f);
            std::fclose(f);
        }
        std::fprintf(stderr, "SYLVA-VALGRIND: the input after which valgrind reported is %s\n",
                     name.c_str());
    }
    return result;
}
