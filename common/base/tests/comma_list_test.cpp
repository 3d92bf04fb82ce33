#include "plexus/base/comma_list.hpp"

#include <gtest/gtest.h>

namespace plexus {
namespace {

using Items = std::vector<std::string>;

TEST(CommaList, ItemsInOrderWithoutEmptyOnes) {
  EXPECT_EQ(split_comma_list("a,b,c"), (Items{"a", "b", "c"}));
  EXPECT_EQ(split_comma_list(",a,,b,"), (Items{"a", "b"}));
  EXPECT_EQ(split_comma_list(""), Items{});
  EXPECT_EQ(split_comma_list(",,"), Items{});
  EXPECT_EQ(split_comma_list("127.0.0.1"), Items{"127.0.0.1"});
  EXPECT_EQ(split_comma_list(" a, b"), (Items{" a", " b"}));  // no trimming
}

}  // namespace
}  // namespace plexus
