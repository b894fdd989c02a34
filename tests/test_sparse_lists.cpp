// The arrangement's per-face and per-edge lists (src/boolean/sparse_lists.hpp): every index
// reads as empty until something is added to it; lists keep what was added, in order;
// lists() holds exactly the lists added to; resize empties everything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "boolean/sparse_lists.hpp"

namespace molsurf::boolean_engine {
namespace {

TEST(SparseLists, EmptyUntilAddedTo) {
  SparseLists<std::uint32_t> lists;
  lists.resize(1000);
  EXPECT_EQ(lists.size(), 1000u);
  for (std::size_t i = 0; i < lists.size(); ++i) EXPECT_TRUE(lists[i].empty());
  EXPECT_TRUE(lists.lists().empty());
  lists.list(7).push_back(3);
  lists.list(999).push_back(1);
  lists.list(7).push_back(2);
  EXPECT_EQ(lists[7], (std::vector<std::uint32_t>{3, 2}));
  EXPECT_EQ(lists[999], (std::vector<std::uint32_t>{1}));
  EXPECT_TRUE(lists[0].empty());
  EXPECT_TRUE(lists[8].empty());
  ASSERT_EQ(lists.lists().size(), 2u) << "one list per index added to";
  // Sorted through lists(), read back through the index.
  for (auto& l : lists.lists()) std::sort(l.begin(), l.end());
  EXPECT_EQ(lists[7], (std::vector<std::uint32_t>{2, 3}));
}

TEST(SparseLists, ResizeEmptiesEveryList) {
  SparseLists<std::pair<std::uint32_t, std::uint32_t>> lists;
  lists.resize(4);
  lists.list(2).emplace_back(1, 2);
  lists.resize(6);
  EXPECT_EQ(lists.size(), 6u);
  for (std::size_t i = 0; i < lists.size(); ++i) EXPECT_TRUE(lists[i].empty());
  EXPECT_TRUE(lists.lists().empty());
  lists.list(5).emplace_back(4, 5);
  EXPECT_EQ(lists[5].size(), 1u);
  EXPECT_TRUE(lists[2].empty());
}

}  // namespace
}  // namespace molsurf::boolean_engine
