# The sources of the extension module hmfnet._hmfnet, listed once for the two builds that compile
# it: the main build (src/CMakeLists.txt, links hmfnet_app from its own tree) and
# `pip install .` (python/CMakeLists.txt, links hmfnet::hmfnet_app from an installed hmfnet).
set(HMFNET_PYTHON_MODULE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/module.cpp
  ${CMAKE_CURRENT_LIST_DIR}/python_commands.cpp
  ${CMAKE_CURRENT_LIST_DIR}/python_network.cpp
)
