// What a file records about how it was made (the sidecars of tables and surrogates):
// when, on which host, by which command line; and durations as people read them.
#pragma once

#include <ctime>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>

namespace viscor::jobs {

/// `t` as an ISO 8601 UTC time, "2026-12-04T22:40:37Z".
inline std::string iso_time_utc(std::time_t t) {
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

/// This machine's host name ("unknown" if it has none).
inline std::string host_name() {
  char buffer[256] = {};
  if (gethostname(buffer, sizeof buffer - 1) != 0) return "unknown";
  return buffer;
}

/// The exact command line of this process (Linux /proc), shell-quoted.
inline std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string line;
  std::size_t start = 0;
  while (start < raw.size()) {
    std::size_t end = raw.find('\0', start);
    if (end == std::string::npos) end = raw.size();
    std::string arg = raw.substr(start, end - start);
    if (arg.empty() || arg.find_first_of(" \t\n'\"\\$`*?;&|<>()") != std::string::npos) {
      std::string quoted = "'";
      for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
      arg = quoted + "'";
    }
    line += (line.empty() ? "" : " ") + arg;
    start = end + 1;
  }
  return line;
}

/// "mm:ss" or "h:mm:ss" ("--:--" for a negative or absurd value).
inline std::string duration_text(double seconds) {
  if (!(seconds >= 0) || seconds > 1e9) return "--:--";
  const long long s = static_cast<long long>(seconds + 0.5);
  std::ostringstream out;
  out << std::setfill('0');
  if (s >= 3600) out << s / 3600 << ':' << std::setw(2) << (s / 60) % 60 << ':' << std::setw(2) << s % 60;
  else out << std::setw(2) << s / 60 << ':' << std::setw(2) << s % 60;
  return out.str();
}

}  // namespace viscor::jobs
