// PlannerLink's side of a local planner's answers: velocity commands on cmd_vel, and a status ABORTED on
// planner_status when it gives up (planner_link.hpp).
#include <actionlib_msgs/GoalStatus.h>

#include "planner_link.hpp"
#include "ppp_msgs/graph_names.h"
#include "ppp_msgs/lockstep_queue.h"

namespace ppp {
namespace agents {

void PlannerLink::subscribeVelocityAnswers() {
  answers_ = ppp_msgs::subscribeLockstep<geometry_msgs::TwistStamped>(
      nh_, ppp_msgs::topics::kPlannerCommand, 10,
      [this](const geometry_msgs::TwistStamped::ConstPtr& command) {
        commands_.put(VelocityAnswer{command->header, *command, std::nullopt});
      },
      queue_.get());
  statuses_ = ppp_msgs::subscribeLockstep<actionlib_msgs::GoalStatus>(
      nh_, ppp_msgs::topics::kPlannerStatus, 10,
      [this](const actionlib_msgs::GoalStatus::ConstPtr& status) {
        if (status->status != actionlib_msgs::GoalStatus::ABORTED) return;  // only giving up answers a request
        VelocityAnswer answer;
        answer.header.stamp = status->goal_id.stamp;
        answer.aborted = status->text;
        commands_.put(answer);
      },
      queue_.get());
}

}  // namespace agents
}  // namespace ppp
