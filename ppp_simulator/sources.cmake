# The sources of the ROS-free simulator libraries (the package build and the fuzz build list them from here).
# The report: pass rates, statistics, plots, animations and the report's pages, from results rows and PPPs.
set(PPP_REPORT_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/report/pass_rates.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/statistics.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/detours.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/reference.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/motion_models.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/svg_plot.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/episode_animation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/continuous_animation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/distinct_failures.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/report/report.cpp
)
# The two animations draw with palettes of their own under the same names: never compiled as one unit (a unity build).
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/src/report/continuous_animation.cpp
  PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
# The experiment: its config, sets, runs, results file and graph, and its report made with the report library.
set(PPP_SIMULATOR_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/scenario_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_config.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/results_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/planner_moves.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/canonical_order.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_report.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/experiment_graph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/simulator_options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/failure_shrink.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/shrink_job.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/corpus.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/hunt_corpus.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/corpus_check.cpp
)
