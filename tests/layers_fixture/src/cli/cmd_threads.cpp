// A front end that does the library's work: check_layers must name this line.
#include <vector>
void run_rows() { std::vector<std::thread> pool; }
