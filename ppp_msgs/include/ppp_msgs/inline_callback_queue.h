#pragma once

#include <functional>
#include <memory>
#include <string>

#include <ros/callback_queue_interface.h>
#include <ros/node_handle.h>
#include <ros/subscribe_options.h>
#include <ros/transport_hints.h>

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

/// Subscribes to `topic` over TCP with Nagle's algorithm off: a lockstep batch protocol's low-latency subscription,
/// its callback run through `queue` (which must outlive the subscription). With an InlineCallbackQueue the callback
/// runs in roscpp's network thread as the message is read: a node in a process of its own. A nodelet takes a
/// HandOverQueue (hand_over.h) or a queue of its own instead: in a nodelet manager a message from a nodelet of the
/// same process is handed over by roscpp in the publisher's own thread, under roscpp's process-wide publish lock,
/// so a callback run there at once would hold up every other publisher in the process for as long as it runs.
///
/// Each message reaches `callback` once. When a subscription and a publisher of the same process are made at the
/// same moment (nodelets loading while others advertise), roscpp can link them twice (TopicManager::subscribe
/// finds the new publisher after asking the master while TopicManager::advertise finds the new subscription, and
/// both add an intra-process link); every message then arrives twice, as the same object. An agent answering a
/// batch twice would take two steps of each episode on one scan, so a message that is the one delivered last is
/// dropped (it is held until the next arrives, so no new message can reuse its address).
template <typename Message>
ros::Subscriber subscribeLockstep(ros::NodeHandle& nh, const std::string& topic, uint32_t queue_size,
                                  const std::function<void(const typename Message::ConstPtr&)>& callback,
                                  ros::CallbackQueueInterface* queue) {
  auto last = std::make_shared<typename Message::ConstPtr>();  // callbacks of one subscription never overlap
  auto once = [callback, last](const typename Message::ConstPtr& message) {
    if (message == *last) return;
    *last = message;
    callback(message);
  };
  ros::SubscribeOptions options = ros::SubscribeOptions::create<Message>(
      topic, queue_size, std::function<void(const typename Message::ConstPtr&)>(once), ros::VoidConstPtr(), queue);
  options.transport_hints = ros::TransportHints().tcpNoDelay();
  return nh.subscribe(options);
}

}  // namespace ppp_msgs
