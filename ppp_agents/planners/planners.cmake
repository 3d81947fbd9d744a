# The example planner nodes (docs/reference/planner-interface.md), included by ppp_agents/CMakeLists.txt. The algorithms
# are a ROS-free library tested without a master; the nodes share one ROS glue library.
find_package(ompl REQUIRED)
find_package(mrpt-nav REQUIRED)
find_package(Threads REQUIRED)

add_library(ppp_planners STATIC
  planners/grid_map.cpp
  planners/optimistic_astar.cpp
  planners/planted_faults.cpp
  planners/grid_motion_validator.cpp
  planners/ompl_grid_planner.cpp
  planners/planner_node_options.cpp
  planners/dynamic_window.cpp
  planners/scan_costmap.cpp
  planners/dwa_planner.cpp
  planners/sector_obstacles.cpp
)
set_target_properties(ppp_planners PROPERTIES POSITION_INDEPENDENT_CODE ON)  # linked into the nodelet library
target_include_directories(ppp_planners PUBLIC planners ${ppp_core_INCLUDE_DIRS} ${CMAKE_CURRENT_SOURCE_DIR}/../ppp_msgs/include)
target_include_directories(ppp_planners SYSTEM PUBLIC ${OMPL_INCLUDE_DIRS})
target_link_libraries(ppp_planners PUBLIC ${ppp_core_LIBRARIES} ${OMPL_LIBRARIES})
target_compile_options(ppp_planners PRIVATE -Wall -Wextra)

# MRPT's wavefront planner and holonomic reactive navigators, in a library of their own so only their nodes and
# tests link MRPT.
add_library(ppp_planners_mrpt STATIC planners/mrpt_grid_planner.cpp planners/mrpt_reactive_navigator.cpp
            planners/reactive_steering.cpp planners/mrpt_laser.cpp planners/mrpt_tpspace_navigator.cpp)
set_target_properties(ppp_planners_mrpt PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(ppp_planners_mrpt PUBLIC ppp_planners mrpt::nav)
target_compile_options(ppp_planners_mrpt PRIVATE -Wall -Wextra)

# The nodes' ROS glue and node classes, shared by the executables and the nodelet library.
add_library(ppp_planners_ros STATIC planners/planner_node.cpp planners/planner_node_parameters.cpp
  planners/optimistic_planner_node.cpp planners/ompl_planner_node.cpp planners/velocity_planner_link.cpp
  planners/dwa_planner_node.cpp planners/zoo_planner_node.cpp planners/echo_planner_node.cpp)
set_target_properties(ppp_planners_ros PROPERTIES POSITION_INDEPENDENT_CODE ON)  # linked into the nodelet library
target_include_directories(ppp_planners_ros SYSTEM PUBLIC ${catkin_INCLUDE_DIRS})
target_link_libraries(ppp_planners_ros PUBLIC ppp_planners ${catkin_LIBRARIES})
target_compile_options(ppp_planners_ros PRIVATE -Wall -Wextra)
add_dependencies(ppp_planners_ros ${catkin_EXPORTED_TARGETS})
add_library(ppp_planners_mrpt_ros STATIC planners/mrpt_planner_node.cpp planners/mrpt_reactive_node.cpp
  planners/mrpt_tpspace_node.cpp)
# The TP-space node's configuration when its ~config is empty: MRPT's example, as shipped in config/.
set_source_files_properties(planners/mrpt_tpspace_node.cpp PROPERTIES COMPILE_DEFINITIONS
  PPP_TPSPACE_DEFAULT_CONFIG="${CMAKE_CURRENT_SOURCE_DIR}/../config/mrpt_tpspace.ini")
set_target_properties(ppp_planners_mrpt_ros PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(ppp_planners_mrpt_ros PUBLIC ppp_planners_ros ppp_planners_mrpt)
target_compile_options(ppp_planners_mrpt_ros PRIVATE -Wall -Wextra)

# Each node as a process of its own (NAME_node, from NAME_main.cpp) ...
foreach(node optimistic_planner ompl_planner dwa_planner zoo_planner echo_planner)
  add_executable(${node}_node planners/${node}_main.cpp)
  target_link_libraries(${node}_node ppp_planners_ros)
  target_compile_options(${node}_node PRIVATE -Wall -Wextra)
endforeach()
foreach(node mrpt_planner mrpt_reactive mrpt_tpspace)
  add_executable(${node}_node planners/${node}_main.cpp)
  target_link_libraries(${node}_node ppp_planners_mrpt_ros)
  target_compile_options(${node}_node PRIVATE -Wall -Wextra)
endforeach()
# ... and as nodelets (nodelet_plugins.xml).
add_library(ppp_planners_nodelets planners/planner_nodelets.cpp)
target_link_libraries(ppp_planners_nodelets ppp_planners_mrpt_ros)
target_compile_options(ppp_planners_nodelets PRIVATE -Wall -Wextra)

install(TARGETS echo_planner_node optimistic_planner_node zoo_planner_node ompl_planner_node dwa_planner_node mrpt_planner_node mrpt_reactive_node mrpt_tpspace_node ppp_planners_nodelets
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
# simple_planner.py, and two variants of it with a classic, rare fault each, for hunting
# (docs/tutorials/hunt-your-planner.md); steering_planner.py, a local planner on simulated time for continuous motion.
catkin_install_python(PROGRAMS scripts/simple_planner.py scripts/horizon_planner.py scripts/greedy_planner.py
                      scripts/steering_planner.py DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(test_name grid_map_test optimistic_astar_test planted_faults_test ompl_grid_planner_test dynamic_window_test dwa_planner_test
                  scan_costmap_test)
    catkin_add_gtest(${test_name} planners/test/${test_name}.cpp)
    target_link_libraries(${test_name} ppp_planners GTest::gtest_main)
    target_compile_options(${test_name} PRIVATE -Wall -Wextra)
  endforeach()
  catkin_add_gtest(mrpt_grid_planner_test planners/test/mrpt_grid_planner_test.cpp)
  target_link_libraries(mrpt_grid_planner_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(mrpt_grid_planner_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(mrpt_tpspace_navigator_test planners/test/mrpt_tpspace_navigator_test.cpp)
  target_link_libraries(mrpt_tpspace_navigator_test ppp_planners_mrpt ppp_agents GTest::gtest_main)
  target_compile_definitions(mrpt_tpspace_navigator_test PRIVATE
    PPP_TPSPACE_CONFIG="${CMAKE_CURRENT_SOURCE_DIR}/../config/mrpt_tpspace.ini")
  target_compile_options(mrpt_tpspace_navigator_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(mrpt_tpspace_source_test planners/test/mrpt_tpspace_source_test.cpp)
  target_link_libraries(mrpt_tpspace_source_test mrpt::nav GTest::gtest_main)
  target_compile_definitions(mrpt_tpspace_source_test PRIVATE
    PPP_TPSPACE_CONFIG="${CMAKE_CURRENT_SOURCE_DIR}/../config/mrpt_tpspace.ini")
  target_compile_options(mrpt_tpspace_source_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(reactive_steering_test planners/test/reactive_steering_test.cpp)
  target_link_libraries(reactive_steering_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(reactive_steering_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(sector_obstacles_test planners/test/sector_obstacles_test.cpp)
  target_link_libraries(sector_obstacles_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(sector_obstacles_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(mrpt_reactive_continuous_test planners/test/mrpt_reactive_continuous_test.cpp)
  target_link_libraries(mrpt_reactive_continuous_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(mrpt_reactive_continuous_test PRIVATE -Wall -Wextra)
  catkin_add_gtest(mrpt_hunted_traps_test planners/test/mrpt_hunted_traps_test.cpp)
  target_link_libraries(mrpt_hunted_traps_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(mrpt_hunted_traps_test PRIVATE -Wall -Wextra)
  # Their pictures for docs/images/reactive-traps-continuous.png.
  add_executable(reactive_trap_pictures planners/test/reactive_trap_pictures.cpp)
  target_link_libraries(reactive_trap_pictures ppp_planners_mrpt)
  target_compile_options(reactive_trap_pictures PRIVATE -Wall -Wextra)
  add_dependencies(tests reactive_trap_pictures)
  # Each committed picture is what the command findings.md shows writes.
  function(trap_picture_test test picture)
    string(REPLACE ";" " " flags "${ARGN}")
    add_test(NAME ${test}
             COMMAND /bin/bash -c "out=$(mktemp --suffix=.png) && trap 'rm -f $out' EXIT && \
$<TARGET_FILE:reactive_trap_pictures> ${flags} $out > /dev/null && \
cmp $out ${CMAKE_CURRENT_SOURCE_DIR}/../docs/images/${picture}")
  endfunction()
  trap_picture_test(reactive_trap_pictures_test reactive-traps-continuous.png)
  trap_picture_test(hunted_nd_trap_pictures_test hunted-nd-traps-continuous.png --hunted ND)
  trap_picture_test(hunted_vff_trap_pictures_test hunted-vff-traps-continuous.png --hunted VFF)
  catkin_add_gtest(mrpt_reactive_navigator_test planners/test/mrpt_reactive_navigator_test.cpp)
  target_link_libraries(mrpt_reactive_navigator_test ppp_planners_mrpt ppp_agents GTest::gtest_main)
  target_compile_options(mrpt_reactive_navigator_test PRIVATE -Wall -Wextra)
  # MRPT's wavefront planner sending a re-planning robot back and forth, and its input checks, called directly.
  catkin_add_gtest(mrpt_livelock_test planners/test/mrpt_livelock_test.cpp)
  target_link_libraries(mrpt_livelock_test ppp_planners_mrpt ppp_agents GTest::gtest_main)
  target_compile_options(mrpt_livelock_test PRIVATE -Wall -Wextra)
  # The continuous model's laser against MRPT's laser simulator.
  catkin_add_gtest(mrpt_laser_test planners/test/mrpt_laser_test.cpp)
  target_link_libraries(mrpt_laser_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(mrpt_laser_test PRIVATE -Wall -Wextra)
  # MRPT's wavefront planner from two threads at once (its trace-back keeps state in function-static variables).
  catkin_add_gtest(mrpt_threads_test planners/test/mrpt_threads_test.cpp)
  target_link_libraries(mrpt_threads_test ppp_planners_mrpt GTest::gtest_main)
  target_compile_options(mrpt_threads_test PRIVATE -Wall -Wextra)
  # MRPT's wavefront planner's defects, each shown by the program of its upstream report (docs/upstream/REPORT),
  # which its test runs and checks the report shows line for line: a goal off the map written outside the grid
  # (under valgrind), the thread race, a path that is not the shortest, notFound for a path that exists, and ND
  # turning away from an open target at its seam.
  function(upstream_report_test program test report)
    add_executable(${program} planners/test/${program}.cpp)
    target_link_libraries(${program} mrpt::nav Threads::Threads)
    target_compile_options(${program} PRIVATE -Wall -Wextra)
    add_dependencies(tests ${program})
    add_test(NAME ${test} COMMAND /bin/bash ${CMAKE_CURRENT_SOURCE_DIR}/planners/test/${test}.sh
             $<TARGET_FILE:${program}> ${CMAKE_CURRENT_SOURCE_DIR}/planners/test/${program}.cpp
             ${CMAKE_CURRENT_SOURCE_DIR}/../docs/upstream/${report})
  endfunction()
  upstream_report_test(mrpt_goal_off_map mrpt_valgrind_test mrpt-goal-off-the-map.md)
  upstream_report_test(mrpt_planner_race mrpt_race_test mrpt-planner-thread-race.md)
  upstream_report_test(mrpt_planner_paths mrpt_paths_test mrpt-planner-paths.md)
  upstream_report_test(mrpt_planner_not_found mrpt_not_found_test mrpt-planner-not-found.md)
  upstream_report_test(mrpt_nd_seam mrpt_seam_test mrpt-nd-seam.md)
  catkin_add_gtest(planner_node_parameters_test planners/test/planner_node_parameters_test.cpp)
  target_link_libraries(planner_node_parameters_test ppp_planners_ros GTest::gtest_main)
  # The local planners' link answers a control period with its own goal and map, whatever order its topics come in.
  add_rostest_gtest(velocity_planner_link_rostest planners/test/velocity_planner_link.test
                    planners/test/velocity_planner_link_rostest.cpp)
  target_link_libraries(velocity_planner_link_rostest ppp_planners_ros)
  target_compile_options(velocity_planner_link_rostest PRIVATE -Wall -Wextra)
  # The planner node plans each episode towards its own goal, and tells a planner with memory when one starts.
  add_rostest_gtest(planner_node_rostest planners/test/planner_node.test planners/test/planner_node_rostest.cpp)
  target_link_libraries(planner_node_rostest ppp_planners_ros)
  target_compile_options(planner_node_rostest PRIVATE -Wall -Wextra)
endif()

# Plan times on a 20x20 map, and laser scans against MRPT's (Google Benchmark): separate executables, never tests.
find_package(benchmark CONFIG QUIET)
if(benchmark_FOUND)
  add_executable(planners_bench planners/bench/planners_bench.cpp)
  target_link_libraries(planners_bench ppp_planners benchmark::benchmark_main)
  add_executable(laser_bench planners/bench/laser_bench.cpp)
  target_link_libraries(laser_bench ppp_planners_mrpt benchmark::benchmark_main)
  target_compile_options(planners_bench PRIVATE -Wall -Wextra)
endif()
# How often MRPT's wavefront planner answers notFound for a path that exists, by distance, on fine random maps
# and on maps as the planner node draws them (a census program, not a test: its counts go in findings.md).
add_executable(mrpt_not_found_census planners/bench/mrpt_not_found_census.cpp)
target_link_libraries(mrpt_not_found_census mrpt::nav)
