#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <delpsc/refine/incidence_lists.h>

using namespace delpsc;

// Random pushes and erases, against one std::vector per id, through lists that spill past the
// inline slots and come back.
TEST_CASE("IncidenceLists keeps the same multisets as a vector per id") {
  using Item = std::uint64_t;
  refine::IncidenceLists<Item> lists;
  std::vector<std::vector<Item>> model;
  std::mt19937_64 rng(11);
  std::size_t spilled_seen = 0;
  Item next = 1;
  for (int step = 0; step < 200000; ++step) {
    // Few ids, so lists get long: every length from 0 to ~40 is visited.
    const auto v = static_cast<std::uint32_t>(rng() % 64 == 0 ? rng() % 5000 : rng() % 24);
    if (model.size() <= v) model.resize(v + 1);
    auto& m = model[v];
    const bool erase = !m.empty() && (rng() % 100 < (m.size() > 30 ? 70u : 45u));
    if (erase) {
      const Item x = m[rng() % m.size()];
      lists.erase_first(v, [x](Item y) { return y == x; });
      m.erase(std::find(m.begin(), m.end(), x));
    } else {
      lists.push(v, next);
      m.push_back(next++);
    }
    spilled_seen += m.size() > refine::IncidenceLists<Item>::kInline;
    if (step % 97 == 0 || erase) {
      std::vector<Item> got(lists[v].begin(), lists[v].end()), want = m;
      std::sort(got.begin(), got.end());
      std::sort(want.begin(), want.end());
      REQUIRE(got == want);
    }
  }
  CHECK(spilled_seen > 1000);
  for (std::uint32_t v = 0; v < model.size(); ++v) {
    std::vector<Item> got(lists[v].begin(), lists[v].end()), want = model[v];
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    CHECK(got == want);
  }
  CHECK(lists[1u << 30].empty());  // an id never pushed to
}

// reserve(n) is the restricted facets' promise that step 2's new vertices (ids below n) do not
// move the lists: pointers into them stay valid. Without it the first push past the size moves
// everything (and copies it to a new block).
TEST_CASE("IncidenceLists::reserve keeps the lists in place while ids fit") {
  using Item = std::uint64_t;
  refine::IncidenceLists<Item> lists;
  lists.reserve(1000);
  lists.push(10, 7);
  const Item* before = lists[10].data();
  for (std::uint32_t v = 11; v < 1000; ++v) lists.push(v, v);
  CHECK(lists[10].data() == before);
  CHECK(lists[10].size() == 1);
  CHECK(lists[10][0] == 7);
  for (std::uint32_t v = 11; v < 1000; ++v) REQUIRE((lists[v].size() == 1 && lists[v][0] == v));
  // Past the reservation the lists move, keeping their contents.
  lists.push(5000, 1);
  CHECK(lists[10][0] == 7);
  CHECK(lists[999][0] == 999);
  CHECK(lists[5000][0] == 1);
}
