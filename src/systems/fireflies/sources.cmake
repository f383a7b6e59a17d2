# The fireflies system's sources (src/CMakeLists.txt includes every
# systems/*/sources.cmake).
list(APPEND atrium_system_sources
  ${CMAKE_CURRENT_LIST_DIR}/fireflies.cpp
  ${CMAKE_CURRENT_LIST_DIR}/firefly_sprites.cpp)
