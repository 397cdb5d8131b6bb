# Warnings for hmfnet's own code (HighFive's HighFiveWarnings.cmake pattern). Third-party headers
# (Trilinos, Eigen, HDF5) are included as SYSTEM so these flags do not fire inside them.
add_library(hmfnet_warnings INTERFACE)
target_compile_options(hmfnet_warnings INTERFACE -Wall -Wextra -Wshadow -Wconversion -Wsign-conversion)
if(HMFNET_WERROR)
  target_compile_options(hmfnet_warnings INTERFACE -Werror)
endif()
