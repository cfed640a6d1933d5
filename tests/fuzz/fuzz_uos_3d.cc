// libFuzzer target: 3DTK .3d scans (internal::ParseUos3d on the bytes).
// Seeds: tests/fuzz/corpus/uos_3d/. Run by .ci/fuzz.

#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string input(reinterpret_cast<const char*>(bytes), size);
  return mlndt::fuzz::FuzzCloudParser(mlndt::internal::ParseUos3d, input);
}
