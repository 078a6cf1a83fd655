// The geometry under the driver: runs, painter's spans, chains, layer order.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "devices/tek4027/tek4027_runs.hpp"

using namespace lattice;
using namespace lattice::tek4027;

namespace {

// Rows of digits, '.' = pot 0 (the background).
PotFrame frameOf(std::initializer_list<std::string> rows) {
  PotFrame f;
  f.height = static_cast<int>(rows.size());
  f.width = static_cast<int>(rows.begin()->size());
  for (const std::string& r : rows)
    for (char c : r) f.pots.push_back(static_cast<std::uint8_t>(c == '.' ? 0 : c - '0'));
  return f;
}

}  // namespace

TEST_CASE("row runs are maximal and skip the background") {
  auto f = frameOf({"..11.22211"});
  auto runs = rowRuns(f, 0);
  REQUIRE(runs.size() == 3);
  CHECK((runs[0].x0 == 2 && runs[0].x1 == 3 && runs[0].pot == 1));
  CHECK((runs[1].x0 == 5 && runs[1].x1 == 7 && runs[1].pot == 2));
  CHECK((runs[2].x0 == 8 && runs[2].x1 == 9 && runs[2].pot == 1));
}

TEST_CASE("painter's spans cross later pots, stop at the background, end on own pixels") {
  auto f = frameOf({"1221.12223"});
  auto spans = coverRuns(f, 0, 1, 1u << 2);
  REQUIRE(spans.size() == 2);
  CHECK((spans[0].x0 == 0 && spans[0].x1 == 3));
  CHECK((spans[1].x0 == 5 && spans[1].x1 == 5));  // the 2s after it lead to no 1
  CHECK(coverRuns(f, 0, 1, 0).size() == 3);
}

TEST_CASE("chains cover exactly the runs they are given") {
  auto f = frameOf({".111..", "..11.1", "1.1111", "....1."});
  std::vector<std::vector<PotRun>> rows;
  std::set<std::pair<int, int>> want;
  for (int y = 0; y < f.height; ++y) {
    rows.push_back(rowRuns(f, y));
    for (const auto& r : rows.back())
      for (int x = r.x0; x <= r.x1; ++x) want.insert({x, y});
  }
  for (bool interior : {false, true})
    for (bool diagonal : {false, true}) {
      ChainOptions options;
      options.enterInterior = interior;
      options.diagonalSteps = diagonal;
      std::set<std::pair<int, int>> drawn;
      std::size_t chains = 0;
      for (const auto& chain : chainRuns(rows, options)) {
        ++chains;
        REQUIRE(chain.size() >= 2);
        for (std::size_t i = 1; i < chain.size(); ++i) {
          const auto a = chain[i - 1], b = chain[i];
          // Segments are horizontal, or one-row steps of at most one column.
          REQUIRE((a.y == b.y || (b.y == a.y + 1 && std::abs(b.x - a.x) <= 1)));
          for (int x = std::min(a.x, b.x); x <= std::max(a.x, b.x); ++x)
            if (a.y == b.y) drawn.insert({x, a.y});
          drawn.insert({a.x, a.y});
          drawn.insert({b.x, b.y});
        }
      }
      INFO("interior " << interior << " diagonal " << diagonal);
      CHECK(drawn == want);
      CHECK(chains < 6);  // 6 runs: some must have been linked
    }
}

TEST_CASE("layer order draws an enclosing shape before what it encloses") {
  auto f = frameOf({"11111111", "12222221", "12233221", "12222221", "11111111"});
  auto order = layerOrder(f);
  CHECK(order == std::vector<int>{1, 2, 3});
}
