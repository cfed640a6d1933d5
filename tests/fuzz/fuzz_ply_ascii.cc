// libFuzzer target: PLY, format ascii (internal::ParsePly on the bytes; the
// format line is forced to ascii).
// Seeds: tests/fuzz/corpus/ply_ascii/. Run by .ci/fuzz.

#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string input(reinterpret_cast<const char*>(bytes), size);
  return mlndt::fuzz::FuzzCloudParser(
      mlndt::internal::ParsePly,
      mlndt::fuzz::ForceLine(input, "format", "format ascii 1.0"));
}
