// Deliberately overflows a 64-bit signed product, as Q alpha once did for a huge
// exponent numerator: the sanitizer build must stop it (tests/CMakeLists.txt
// expects UndefinedBehaviorSanitizer's report). Built only with VISCOR_SANITIZE.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  // From the command line, so the compiler cannot fold it: 4611686018427387905 * 4.
  const std::int64_t numerator = argc > 1 ? std::strtoll(argv[1], nullptr, 10) : 4611686018427387905LL;
  const std::int64_t q = argc > 2 ? std::strtoll(argv[2], nullptr, 10) : 4;
  std::printf("%lld\n", static_cast<long long>(numerator * q));
  return 0;
}
