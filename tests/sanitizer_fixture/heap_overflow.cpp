// Deliberately reads one element past a heap array: the sanitizer build must stop
// it (tests/CMakeLists.txt expects AddressSanitizer's report). Built only with
// VISCOR_SANITIZE; an ordinary build would print the stray value and exit 0.
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char**) {
  std::vector<int> v(static_cast<std::size_t>(argc) + 3, 1);
  const int* data = v.data();
  std::printf("%d\n", data[v.size()]);  // one past the end
  return 0;
}
