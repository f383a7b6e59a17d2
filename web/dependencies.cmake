# The WebAssembly build's dependencies: Debian's header-only libraries, seen by
# emcc through a folder of links to them (-I/usr/include would bring in the
# host's C library headers), behind the same target names the native build
# finds, so that src/CMakeLists.txt links the same way on both.
set(atrium_host_headers ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${atrium_host_headers})
foreach(folder glm nlohmann epoxy CLI stb)
  if(NOT EXISTS /usr/include/${folder})
    message(FATAL_ERROR "/usr/include/${folder} is missing: run scripts/install-deps.sh")
  endif()
  file(CREATE_LINK /usr/include/${folder} ${atrium_host_headers}/${folder} SYMBOLIC)
endforeach()
# tinyobjloader is one header in /usr/include itself.
if(NOT EXISTS /usr/include/tiny_obj_loader.h)
  message(FATAL_ERROR "/usr/include/tiny_obj_loader.h is missing: run scripts/install-deps.sh")
endif()
file(MAKE_DIRECTORY ${atrium_host_headers}/tinyobjloader)
file(CREATE_LINK /usr/include/tiny_obj_loader.h ${atrium_host_headers}/tinyobjloader/tiny_obj_loader.h SYMBOLIC)

function(atrium_header_target name include_dir)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${include_dir})
endfunction()
atrium_header_target(glm::glm ${atrium_host_headers})
atrium_header_target(nlohmann_json::nlohmann_json ${atrium_host_headers})
atrium_header_target(CLI11::CLI11 ${atrium_host_headers})
atrium_header_target(PkgConfig::EPOXY ${atrium_host_headers})
atrium_header_target(PkgConfig::STB ${atrium_host_headers}/stb)
atrium_header_target(tinyobjloader::header ${atrium_host_headers}/tinyobjloader)
