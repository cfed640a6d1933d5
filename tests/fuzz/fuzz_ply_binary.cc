// libFuzzer target: PLY, binary_little_endian and binary_big_endian
// (internal::ParsePly on the bytes; an ascii format line becomes
// binary_little_endian, the seeds hold both byte orders).
// Seeds: tests/fuzz/corpus/ply_binary/. Run by .ci/fuzz.

#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string input(reinterpret_cast<const char*>(bytes), size);
  return mlndt::fuzz::FuzzCloudParser(
      mlndt::internal::ParsePly,
      mlndt::fuzz::ForceLine(
          input, "format ascii", "format binary_little_endian 1.0"));
}
