# Helpers shared by every module and app: one place for warnings and sanitizers.

function(lvf_set_compile_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(LVF_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(LVF_SANITIZE OR LVF_FUZZ)
    # Undefined behaviour aborts (as an address error does) instead of
    # printing and going on, so that a test or a fuzz run that meets it fails.
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=undefined
      -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=undefined)
    # GCC 12's -Wmaybe-uninitialized misfires inside libstdc++'s std::function
    # and std::regex once the sanitizers instrument them
    # (test_lvf_simulate_cli): kept a warning, not an error, in these builds.
    if(LVF_WARNINGS_AS_ERRORS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized)
    endif()
  endif()
  if(LVF_FUZZ)
    # Coverage for libFuzzer in every module; the fuzz targets link its main.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()

# lvf_add_module(NAME <name> SOURCES ... DEPENDS ...)
# Builds libs/<name> as the static library lvfusion-<name> (alias lvf::<name>) with
# its public headers under include/lvfusion/<name>/. Installed with its headers
# and exported as lvf::<name> in the lvfusion CMake package (find_package(lvfusion)).
function(lvf_add_module)
  cmake_parse_arguments(M "" "NAME" "SOURCES;DEPENDS" ${ARGN})
  set(target lvfusion-${M_NAME})
  add_library(${target} STATIC ${M_SOURCES})
  add_library(lvf::${M_NAME} ALIAS ${target})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(${target} PUBLIC ${M_DEPENDS})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${M_NAME})
  lvf_set_compile_options(${target})
  install(TARGETS ${target} EXPORT lvfusionTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# lvf_add_app(NAME <name> SOURCES ... DEPENDS ... [NO_INSTALL])
# Installed into bin/ unless NO_INSTALL; the apps find share/lvfusion beside
# bin/ once installed (ShippedFiles.h), the source tree's before.
function(lvf_add_app)
  cmake_parse_arguments(A "NO_INSTALL" "NAME" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${A_NAME} ${A_SOURCES})
  target_link_libraries(${A_NAME} PRIVATE ${A_DEPENDS})
  target_compile_definitions(${A_NAME} PRIVATE
    LVF_SHARE_DIR="${LVF_SHARE_DIR}" LVF_SAMPLES_DIR="${LVF_SAMPLES_DIR}")
  lvf_set_compile_options(${A_NAME})
  if(NOT A_NO_INSTALL)
    install(TARGETS ${A_NAME} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endfunction()
