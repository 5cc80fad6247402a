// Fuzz target: checksum manifests (SHA256SUMS beside committed data, what sha256sum
// writes): core/checksums.hpp, parse_checksum_manifest. Checks beyond "no crash":
// every entry accepted is 64 lowercase hex digits and the name of a file of the
// manifest's own directory, no name is listed twice, and the manifest viscor writes
// from the entries ("<sha256>  <name>" lines) reads back to the same entries.
#include "fuzz_support.hpp"

#include <viscor/core/checksums.hpp>

#include <set>

namespace {

using viscor::fuzz::fuzz_require;

void check(const std::vector<viscor::checksum_entry>& entries) {
  std::set<std::string> names;
  std::string written;
  for (const auto& e : entries) {
    fuzz_require(e.sha256.size() == 64 && e.sha256.find_first_not_of("0123456789abcdef") == std::string::npos,
                 "an accepted checksum is not 64 lowercase hex digits: '" + e.sha256 + "'");
    fuzz_require(!e.name.empty() && e.name.find('/') == std::string::npos && e.name != "." && e.name != "..",
                 "an accepted name is not a file of the manifest's directory: '" + e.name + "'");
    fuzz_require(names.insert(e.name).second, "a name accepted twice: '" + e.name + "'");
    written += e.sha256 + "  " + e.name + "\n";
  }
  const auto again = viscor::parse_checksum_manifest(written, "written");
  fuzz_require(again.size() == entries.size(), "the written manifest reads back to other entries");
  for (std::size_t i = 0; i < again.size(); ++i)
    fuzz_require(again[i].sha256 == entries[i].sha256 && again[i].name == entries[i].name,
                 "the written manifest reads back to other entries");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 65536) return 0;
  const std::string text = viscor::fuzz::text_of(data, size);
  viscor::fuzz::refusal_or_result([&] { check(viscor::parse_checksum_manifest(text, "SHA256SUMS")); });
  return 0;
}
