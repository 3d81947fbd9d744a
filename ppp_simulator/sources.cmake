# The sources of the ROS-free ppp_simulator library (the package build and the fuzz build list them from here).
set(PPP_SIMULATOR_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/episode_animation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/scenario_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_config.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/results_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/canonical_order.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_graph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/simulator_options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/pass_rates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/statistics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/svg_plot.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report.cpp
)
