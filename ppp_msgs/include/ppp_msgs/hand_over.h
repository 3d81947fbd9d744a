#pragma once

#include <vector>

#include <ros/callback_queue.h>
#include <ros/publisher.h>

namespace ppp_msgs {

// Same-thread hand-over between nodelets of one manager, for lockstep protocols.
//
// roscpp hands a message to a subscriber of the same process in the publisher's thread, under its process-wide
// publish lock, and the subscriber's callback queue decides where the callback runs. A nodelet's own thread
// costs two thread wake-ups per round trip (the answerer's, then the asker's); running the callback at once
// would hold roscpp's publish lock, and with it every other publisher of the process, for as long as it runs.
// A HandOverQueue does neither when the publisher asked for it: publishHandingOver() publishes, and the callbacks
// its message queued are then run in the publisher's thread, after publish() returned. Every other message (from
// another process, or published in another way) goes to the queue itself, which the nodelet serves from a thread
// of its own.

namespace hand_over {

/// The callbacks queued for the calling thread by its publishHandingOver() in progress.
struct Pending {
  bool active = false;
  std::vector<ros::CallbackInterfacePtr> callbacks;
};

/// The calling thread's pending hand-overs: one per thread in the process, whichever library asks (so it is
/// defined once, in ppp_msgs_conversions).
Pending& pending();

}  // namespace hand_over

/// A callback queue that runs a callback in the thread that published its message, when that thread publishes
/// with publishHandingOver(); otherwise it queues it as a ros::CallbackQueue does (serve it with an AsyncSpinner).
class HandOverQueue : public ros::CallbackQueue {
 public:
  void addCallback(const ros::CallbackInterfacePtr& callback, uint64_t owner_id) override {
    hand_over::Pending& pending = hand_over::pending();
    if (pending.active) {
      // roscpp empties a subscription's queue when it unsubscribes (waiting for a call in progress), so a callback
      // handed over after that finds nothing to call.
      pending.callbacks.push_back(callback);
    } else {
      ros::CallbackQueue::addCallback(callback, owner_id);
    }
  }
};

/// Publishes `message`; the callbacks it queued on HandOverQueues are then run in this thread, each before this
/// returns. A lockstep asker's reply is then already in its own queue.
template <typename Message>
void publishHandingOver(const ros::Publisher& publisher, const Message& message) {
  hand_over::Pending& pending = hand_over::pending();
  pending.active = true;
  try {
    publisher.publish(message);
  } catch (...) {
    pending.active = false;
    pending.callbacks.clear();
    throw;
  }
  pending.active = false;
  std::vector<ros::CallbackInterfacePtr> callbacks;
  callbacks.swap(pending.callbacks);  // a callback may publish handing over in turn
  for (const ros::CallbackInterfacePtr& callback : callbacks) {
    while (callback->call() == ros::CallbackInterface::TryAgain) {
    }
  }
}

}  // namespace ppp_msgs
