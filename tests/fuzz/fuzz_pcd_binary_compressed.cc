// libFuzzer target: PCD with DATA binary_compressed (LZF;
// internal::ParsePcd on the bytes; the DATA line is forced).
// Seeds: tests/fuzz/corpus/pcd_binary_compressed/. Run by .ci/fuzz.

#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string input(reinterpret_cast<const char*>(bytes), size);
  return mlndt::fuzz::FuzzCloudParser(
      mlndt::internal::ParsePcd,
      mlndt::fuzz::ForceLine(input, "DATA", "DATA binary_compressed"));
}
