// libFuzzer target: plain .xyz / .txt text (internal::ParseXyzText on the
// bytes).
// Seeds: tests/fuzz/corpus/xyz/. Run by .ci/fuzz.

#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string input(reinterpret_cast<const char*>(bytes), size);
  return mlndt::fuzz::FuzzCloudParser(mlndt::internal::ParseXyzText, input);
}
