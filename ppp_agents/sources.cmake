# The sources of the ROS-free ppp_agents library (the package build and the fuzz build list them from here).
set(PPP_AGENTS_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/action.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/agent_config.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/agent_memory.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/agent_registry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/agent_host.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/navigation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/astar_agent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/random_agent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/wall_follower_agent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/reveal_counter.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/explorer_agent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/bumper_agent.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/path_follower.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/planner_episode.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/protocol/batch_types.cpp
)
