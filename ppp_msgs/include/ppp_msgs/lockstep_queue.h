#pragma once

#include <memory>

#include <ros/callback_queue.h>
#include <ros/spinner.h>

#include "ppp_msgs/hand_over.h"
#include "ppp_msgs/inline_callback_queue.h"

namespace ppp_msgs {

/// Where a lockstep node's callbacks run. In a process of its own: in roscpp's network thread as each message is
/// read (InlineCallbackQueue). As a nodelet: in the thread of a nodelet of the same manager that published the
/// message handing over (HandOverQueue), and every other callback in one thread of the node's own. Declare it before
/// the subscriptions that use it: they unsubscribe first, then its thread stops.
class LockstepQueue {
 public:
  explicit LockstepQueue(bool in_network_thread) {
    if (in_network_thread) {
      queue_ = std::make_unique<InlineCallbackQueue>();
      return;
    }
    auto queue = std::make_unique<HandOverQueue>();
    spinner_ = std::make_unique<ros::AsyncSpinner>(1, queue.get());
    queue_ = std::move(queue);
    spinner_->start();
  }
  LockstepQueue(const LockstepQueue&) = delete;
  LockstepQueue& operator=(const LockstepQueue&) = delete;

  /// The queue to subscribe with.
  ros::CallbackQueueInterface* get() { return queue_.get(); }

 private:
  std::unique_ptr<ros::CallbackQueueInterface> queue_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;  // declared last: stops before the queue goes
};

}  // namespace ppp_msgs
