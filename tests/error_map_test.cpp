// Error maps: the file format (round trip, errors naming file, line and field),
// lookup semantics, the builder's rules, and that a map's bounds hold between its
// samples (linear law: references from the closed form, independent of solve_impact).
#include "test_utils.hpp"

#include <viscor/scenes/error_map_builder.hpp>
#include <viscor/exact/exact_solutions.hpp>
#include <viscor/certify/extern_templates.hpp>

#include <random>
#include <string>

namespace viscor {
namespace {

// Reference points of the linear law from its closed form at 40 digits.
std::vector<reference_point> linear_reference(const std::vector<std::string>& gammas,
                                              const std::vector<std::string>& gs) {
  std::vector<reference_point> out;
  with_working_precision(40, [&]<class Real>() {
    for (const auto& gamma : gammas)
      for (const auto& g : gs) {
        const auto r = exact_cor(law_by_name("linear"), parse_real<Real>(gamma, "gamma"), parse_real<Real>(g, "g"));
        out.push_back({gamma, g, to_decimal_string(r->e), r->outcome});
      }
  });
  return out;
}

const std::vector<std::string> gamma_edges{"1e-4", "1e-3", "1e-2", "3e-2", "0.1", "0.3"};
const std::vector<std::string> g_edges{"-0.5", "0", "0.05", "0.5", "2"};

error_map linear_map(double safety = 4) {
  error_map_spec spec;
  spec.gamma_edges = gamma_edges, spec.g_edges = g_edges;
  spec.safety_factor = safety;
  spec.metadata = {{"reference", "closed form at 40 digits"}};
  return build_error_map(law_by_name("linear"), linear_reference(grid_nodes(gamma_edges, 2), grid_nodes(g_edges, 2)),
                         spec);
}

TEST(error_map, bounds_hold_between_the_samples) {
  const error_map map = linear_map();
  ASSERT_EQ(map.cells().size(), (gamma_edges.size() - 1) * (g_edges.size() - 1));
  const cor_approximations<double> approx(law_by_name("linear"));
  std::mt19937_64 rng(20240607);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int n = 0; n < 400; ++n) {
    const double gamma = std::pow(10.0, -4 + u(rng) * std::log10(3000.0));
    const double g = -0.5 + 2.5 * u(rng);
    const std::optional<map_bounds> b = map.at(gamma, g);
    if (!b) continue;
    const auto exact = exact_cor(law_by_name("linear"), mpfr_50(gamma), mpfr_50(g));
    for (std::size_t k = 0; k < all_approximations.size(); ++k) {
      if (!b->bound[k]) continue;
      const std::optional<double> a = approximate_e(approx, all_approximations[k], gamma, g);
      ASSERT_TRUE(a.has_value());
      const double err = std::abs(*a - static_cast<double>(exact->e));
      EXPECT_LE(err, *b->bound[k]) << to_string(all_approximations[k]) << " at gamma = " << gamma << ", g = " << g;
      ++checked;
    }
  }
  EXPECT_GT(checked, 400);
}

TEST(error_map, file_round_trip) {
  const error_map map = linear_map();
  const std::string text = error_map_text(map);
  const error_map back = parse_error_map(text, "linear.csv");
  EXPECT_EQ(error_map_text(back), text);
  EXPECT_EQ(back.law.name, "linear");
  EXPECT_EQ(back.safety_factor, 4.0);
  ASSERT_EQ(back.cells().size(), map.cells().size());
  for (std::size_t i = 0; i < map.cells().size(); ++i)
    for (std::size_t k = 0; k < all_approximations.size(); ++k) {
      ASSERT_EQ(back.cells()[i].bound[k].has_value(), map.cells()[i].bound[k].has_value());
      if (map.cells()[i].bound[k]) {  // printed rounded up, never down
        EXPECT_GE(*back.cells()[i].bound[k], *map.cells()[i].bound[k]);
        EXPECT_LE(*back.cells()[i].bound[k], *map.cells()[i].bound[k] * 1.03);
      }
    }
  EXPECT_NE(text.find("# reference=closed form at 40 digits"), std::string::npos);
  // large_g does not apply for g < 0, Schwager-Poschel only to Kuwabara-Kono.
  const auto b = back.at(0.005, -0.25);
  ASSERT_TRUE(b.has_value());
  EXPECT_FALSE(b->bound[1].has_value());
  EXPECT_FALSE(b->bound[2].has_value());
  EXPECT_TRUE(b->bound[0].has_value());
}

TEST(error_map, lookup_outside_and_on_edges) {
  const error_map map = linear_map();
  EXPECT_FALSE(map.at(0.5, 0.1).has_value());    // gamma beyond the last edge
  EXPECT_FALSE(map.at(1e-5, 0.1).has_value());   // below the first
  EXPECT_FALSE(map.at(0.01, 3.0).has_value());   // g beyond
  EXPECT_TRUE(map.at(1e-4, -0.5).has_value());   // the corner of the map
  EXPECT_TRUE(map.at(1e-4, 2.0).has_value());
  EXPECT_FALSE(map.at(0.3, 2.0).has_value());    // in a cell the sticking threshold crosses
  // On a shared edge the smaller bound of the two cells is used; both are valid.
  const auto left = map.at(0.005, 0.01), right = map.at(0.02, 0.01), edge = map.at(0.01, 0.01);
  ASSERT_TRUE(left && right && edge);
  EXPECT_EQ(*edge->bound[0], std::min(*left->bound[0], *right->bound[0]));
}

TEST(error_map, builder_needs_corners_and_drops_bounds_across_the_threshold) {
  // Linear law: sticking from gamma_c = 0.0359 at g = 2 (0.29 at g = 0.5); the cell
  // [0.01, 0.03] x [0.5, 2] stays clean, [0.03, 0.1] x [0.5, 2] is crossed by the threshold.
  const std::vector<std::string> ge{"0.01", "0.03", "0.1"}, gg{"0.5", "2"};
  error_map_spec spec;
  spec.gamma_edges = ge, spec.g_edges = gg;
  const error_map map = build_error_map(law_by_name("linear"), linear_reference(grid_nodes(ge, 2), grid_nodes(gg, 2)), spec);
  ASSERT_EQ(map.cells().size(), 2u);
  EXPECT_EQ(map.cells()[0].outcome, cell_outcome::rebound);
  EXPECT_EQ(map.cells()[1].outcome, cell_outcome::mixed);
  for (const auto& b : map.cells()[1].bound) EXPECT_FALSE(b.has_value());
  EXPECT_FALSE(map.at(0.05, 1.0).has_value());
  EXPECT_TRUE(map.at(0.02, 1.0).has_value());
  // Without the corner (0.03, 2) neither cell is mapped.
  std::vector<reference_point> points = linear_reference(grid_nodes(ge, 2), grid_nodes(gg, 2));
  std::erase_if(points, [](const reference_point& p) { return p.gamma == "0.03" && p.g == "2"; });
  EXPECT_TRUE(build_error_map(law_by_name("linear"), points, spec).cells().empty());
}

TEST(error_map, parse_errors_name_file_line_and_field) {
  const std::string good = error_map_text(linear_map());
  auto error_of = [](const std::string& text) {
    try {
      parse_error_map(text, "m.csv");
    } catch (const parse_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Break one field of the first data row (line 8: 2 comment lines, law, alpha,
  // beta, safety_factor, floor, reference, header -> first row is line 10).
  std::string bad = good;
  const auto row = bad.find("\n1e-4,1e-3,-0.5,0,") + 1;
  bad.replace(row, 4, "abc");
  EXPECT_NE(error_of(bad).find("m.csv:10, field gamma_lo"), std::string::npos) << error_of(bad);
  std::string wrong_outcome = good;
  wrong_outcome.replace(wrong_outcome.find(",rebound,"), 9, ",bounce,");
  EXPECT_NE(error_of(wrong_outcome).find("field outcome"), std::string::npos);
  std::string no_safety = good;
  no_safety.erase(no_safety.find("# safety_factor=4\n"), 18);
  EXPECT_NE(error_of(no_safety).find("safety_factor"), std::string::npos);
  EXPECT_NE(error_of("").find("no column header"), std::string::npos);
  std::string short_row = good.substr(0, good.rfind(',')) + "\n";
  EXPECT_NE(error_of(short_row).find("fields"), std::string::npos) << error_of(short_row);
  std::string unknown_law = good;
  unknown_law.replace(unknown_law.find("# law=linear"), 12, "# law=lineal");
  EXPECT_NE(error_of(unknown_law).find("unknown contact law 'lineal'"), std::string::npos);
  EXPECT_THROW(read_error_map("/nonexistent/map.csv"), parse_error);
}

TEST(error_map, edges_out_of_double_refused_and_nodes_finite) {
  // An edge that under- or overflows double is refused naming it (1e-400 used to become
  // an edge of 0 silently); nodes between edges far apart stay finite and positive.
  auto message = [](const std::vector<std::string>& edges) {
    try {
      grid_nodes(edges, 2);
    } catch (const invalid_parameter& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({"1e-400", "1"}).find("1e-400 underflows"), std::string::npos) << message({"1e-400", "1"});
  EXPECT_NE(message({"1", "1e400"}).find("1e400 overflows"), std::string::npos) << message({"1", "1e400"});
  EXPECT_NE(message({"1", "x"}).find("'x'"), std::string::npos) << message({"1", "x"});
  const std::vector<std::string> nodes = grid_nodes({"1e-300", "1e300"}, 2);
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_EQ(nodes[0], "1e-300");
  EXPECT_PRED_FORMAT3(test::relative_close<double>, std::stod(nodes[1]), 1.0, 1e-12) << nodes[1];
  EXPECT_EQ(nodes[2], "1e300");
  const std::vector<std::string> signed_nodes = grid_nodes({"-1.5e308", "1.5e308"}, 2);
  ASSERT_EQ(signed_nodes.size(), 3u);
  EXPECT_EQ(std::stod(signed_nodes[1]), 0.0) << signed_nodes[1];
}

}  // namespace
}  // namespace viscor
