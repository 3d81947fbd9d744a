#pragma once

#include <ros/callback_queue_interface.h>

namespace ppp_msgs {

/// A callback queue that runs each callback at once, in the thread that delivers it: for a subscription, roscpp's
/// network thread, which reads the message, calls the callback and writes what the callback publishes without
/// handing either over to another thread. A batch-answering node that waits for nothing else saves two thread
/// wake-ups per message this way. Callbacks must be short-lived and must not block: no other message of the
/// node is read meanwhile. Callbacks that ask to be tried again are tried again at once.
class InlineCallbackQueue : public ros::CallbackQueueInterface {
 public:
  /// Runs `callback` now.
  void addCallback(const ros::CallbackInterfacePtr& callback, uint64_t /*owner_id*/) override {
    while (callback->call() == ros::CallbackInterface::TryAgain) {
    }
  }
  /// Nothing is ever queued, so there is nothing to remove.
  void removeByID(uint64_t /*owner_id*/) override {}
};

}  // namespace ppp_msgs
