# The sources of the ROS-free ppp_generator library (the package build and the fuzz build list them from here).
set(PPP_GENERATOR_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/src/breeder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/diversity.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/fitness.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/generator_options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/genetic_algorithm.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/map_elites.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/set_evolution.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/problem_set.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/set_csv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/set_export.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/taxonomy.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/newick.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/tree_json.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/tree_html.cpp
  ${CMAKE_CURRENT_LIST_DIR}/src/diverse_selection.cpp
)
