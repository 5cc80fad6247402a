// Shared by the fuzz targets of tests/fuzz (docs/robustness.md): what counts as a
// finding. A reader may refuse its input with viscor::error (the clear message
// the CLI prints, exit 2); any other exception (std::out_of_range from a
// conversion, a JSON library's own error, std::bad_alloc) escaping a reader is a
// finding, as is a failed check of what the reader returned (fuzz_require).
// Crashes, leaks, undefined behaviour and hangs are found by the sanitizers and
// libFuzzer themselves.
#pragma once

#include <viscor/core/exceptions.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace viscor::fuzz {

/// The input as text (bytes as given, NUL included).
inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// Stops the run with `what` when `ok` is false: a finding.
inline void fuzz_require(bool ok, const std::string& what) {
  if (ok) return;
  std::fprintf(stderr, "viscor fuzz check failed: %s\n", what.c_str());
  std::abort();
}

/// Runs `body`; a viscor::error is an accepted refusal, any other exception a finding.
template <class Body>
void refusal_or_result(Body&& body) {
  try {
    body();
  } catch (const viscor::error&) {
  } catch (const std::exception& e) {
    fuzz_require(false, std::string("an exception other than viscor::error escaped: ") + e.what());
  }
}

/// Splits text into lines ('\n'), the last one without its terminator.
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    out.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace viscor::fuzz
