#include "ppp_msgs/hand_over.h"

namespace ppp_msgs {
namespace hand_over {

Pending& pending() {
  thread_local Pending state;
  return state;
}

}  // namespace hand_over
}  // namespace ppp_msgs
