// subscribeLockstep delivers each message once, even when roscpp links a subscriber to a publisher of its own
// process twice: a subscription made in one thread while another thread advertises the same topic, as nodelets
// loading into a manager do.
#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "ppp_msgs/MoveBatch.h"
#include "ppp_msgs/inline_callback_queue.h"

namespace {

constexpr int kTopics = 60;

/// One topic whose publisher and lockstep subscriber are made at the same moment in two threads, then a plain
/// subscriber (which shares the lockstep one's links: roscpp has one subscription per topic and process).
struct RacedTopic {
  ros::Publisher publisher;
  ros::Subscriber lockstep;
  ros::Subscriber plain;
  std::atomic<int> lockstep_calls{0};
  std::atomic<int> plain_calls{0};
};

void race(ros::NodeHandle& nh, const std::string& topic, std::chrono::microseconds advertise_after, RacedTopic* t) {
  std::thread subscriber([&] {
    t->lockstep = ppp_msgs::subscribeLockstep<ppp_msgs::MoveBatch>(
        nh, topic, 10, [t](const ppp_msgs::MoveBatch::ConstPtr&) { ++t->lockstep_calls; },
        ros::getGlobalCallbackQueue());
  });
  std::this_thread::sleep_for(advertise_after);  // into the subscriber's call to the master
  t->publisher = nh.advertise<ppp_msgs::MoveBatch>(topic, 10);
  subscriber.join();
  t->plain = nh.subscribe<ppp_msgs::MoveBatch>(topic, 10,
                                              [t](const ppp_msgs::MoveBatch::ConstPtr&) { ++t->plain_calls; });
}

TEST(LockstepSubscription, EachMessageOnceWhenRoscppLinksTwice) {
  ros::NodeHandle nh;
  std::vector<std::unique_ptr<RacedTopic>> topics;
  for (int i = 0; i < kTopics; ++i) {
    topics.push_back(std::make_unique<RacedTopic>());
    race(nh, "/raced_" + std::to_string(i), std::chrono::microseconds(50 * (i % 30)), topics.back().get());
  }
  const int kMessages = 3;
  for (auto& t : topics) {
    for (int m = 0; m < kMessages; ++m) t->publisher.publish(boost::make_shared<ppp_msgs::MoveBatch>());
  }
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
  auto delivered = [&] {
    for (const auto& t : topics) {
      if (t->plain_calls < kMessages || t->lockstep_calls < kMessages) return false;
    }
    return true;
  };
  while (!delivered() && ros::WallTime::now() < deadline) ros::spinOnce();
  ros::WallDuration(0.2).sleep();  // a second copy, if any, arrives now
  ros::spinOnce();
  int linked_twice = 0;
  for (int i = 0; i < kTopics; ++i) {
    const RacedTopic& t = *topics[i];
    EXPECT_EQ(t.lockstep_calls, kMessages) << "topic " << i;
    if (t.plain_calls == 2 * kMessages) ++linked_twice;
    EXPECT_TRUE(t.plain_calls == kMessages || t.plain_calls == 2 * kMessages) << "topic " << i << ": "
                                                                              << t.plain_calls;
  }
  // The race is real: some topics were linked twice (their plain subscriber got every message twice).
  EXPECT_GT(linked_twice, 0);
  std::printf("topics linked twice by roscpp: %d of %d\n", linked_twice, kTopics);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "lockstep_subscription_test");
  ros::NodeHandle nh;  // starts the node before the test threads race
  return RUN_ALL_TESTS();
}
