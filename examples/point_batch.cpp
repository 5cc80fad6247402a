// Many impacts in one call, the way `viscor cor --points FILE` reads them: CSV
// with a header (or JSON lines) naming the law, gamma, g and optionally digits.
// Each result is the object `viscor cor --json` prints, plus the input line; a bad
// point is refused on its own line and the others are still solved.
#include <viscor/viscor.hpp>

#include <iostream>
#include <sstream>

int main() {
  std::istringstream points(
      "law,gamma,g,digits\n"
      "tsuji,0.1,0.5,20\n"
      "kuwabara_kono,0.05,1,30\n"
      "hunt_crossley,0.3,0,\n"   // digits empty: the default below
      "tsuji,-1,0,\n");          // refused: gamma < 0
  viscor::jobs::point_options options;
  options.default_digits = 15;
  options.threads = 2;
  int solved = 0;
  const std::size_t refused =
      viscor::jobs::solve_points(points, "example points", options, [&](const viscor::jobs::json& result) {
        if (result.contains("error")) {
          std::cout << "line " << result["line"] << ": refused: " << result["error"].get<std::string>() << "\n";
          return;
        }
        ++solved;
        std::cout << "line " << result["line"] << ": " << result["law"]["name"].get<std::string>()
                  << " e = " << result["e"].get<std::string>() << " (" << result["outcome"].get<std::string>()
                  << ", " << result["precision"]["digits"] << " digits)\n";
      });
  return solved == 3 && refused == 1 ? 0 : 1;
}
