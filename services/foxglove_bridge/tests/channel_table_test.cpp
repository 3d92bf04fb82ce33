// ChannelTable: topics appearing, going, changing type, coming back with their old id.
#include <gtest/gtest.h>

#include "channel_table.hpp"
#include "plexus/msg/messages.hpp"

namespace plexus::foxglove {
namespace {

TEST(ChannelTable, TopicsComeAndGoAndKeepTheirIds) {
  const auto* pose = &msg::type_support<msg::Pose2D>();
  const auto* pos = &msg::type_support<msg::PositionMeasurement>();
  ChannelTable t;
  auto d = t.update({{"r1/position", pos}, {"r1/truth/state", pose}});
  ASSERT_EQ(d.added.size(), 2u);
  EXPECT_TRUE(d.removed.empty());
  const uint32_t position_id = d.added[0].topic == "r1/position" ? d.added[0].id : d.added[1].id;
  EXPECT_TRUE(t.update({{"r1/position", pos}, {"r1/truth/state", pose}}).added.empty());
  d = t.update({{"r1/truth/state", pose}});  // the plant went
  EXPECT_EQ(d.removed, std::vector<uint32_t>{position_id});
  EXPECT_EQ(t.find(position_id), nullptr);
  d = t.update({{"r1/position", pos}, {"r1/truth/state", pose}});  // and came back
  ASSERT_EQ(d.added.size(), 1u);
  EXPECT_EQ(d.added[0].id, position_id);
  d = t.update({{"r1/position", pose}, {"r1/truth/state", pose}});  // another type: another channel
  ASSERT_EQ(d.added.size(), 1u);
  EXPECT_NE(d.added[0].id, position_id);
  EXPECT_EQ(d.removed, std::vector<uint32_t>{position_id});
  ASSERT_NE(t.find(d.added[0].id), nullptr);
  EXPECT_EQ(t.find(d.added[0].id)->type, pose);
  EXPECT_EQ(t.all().size(), 2u);
}

}  // namespace
}  // namespace plexus::foxglove
