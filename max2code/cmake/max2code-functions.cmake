# max2code's CMake package: max2code_generate() and the max2code::runtime target.
#
# Loaded by the max2codeConfig.cmake that `max2code runtime --cmake-dir` writes (and whose folder
# it prints), after it has set MAX2CODE_COMMAND to the command that runs that same max2code:
#
#   cmake -S . -B build -Dmax2code_DIR="$(max2code runtime --cmake-dir)"
#
#   find_package(max2code REQUIRED)
#   add_executable(collide main.c)
#   max2code_generate(CIRCLES_H MXM circles.mxm TARGET collide)     # builds circles.h
#   target_link_libraries(collide PRIVATE max2code::runtime)        # the C runtime, with GSL
#
# max2code_generate(<out_var> MXM <file.mxm> [LANG c|m2|python|rust] [OUTPUT <name>]
#                   [TARGET <target>] [OPTIONS <max2code options>...])
#   Generates ${CMAKE_CURRENT_BINARY_DIR}/<name> (default: the .mxm's stem with the language's
#   extension; a Modula-2 module also writes the .def beside it) and sets <out_var> to its path.
#   Its dependencies (the .mxm and whatever its Maxima program loads) come from the depfile
#   max2code writes, so editing either regenerates. With TARGET, the output is added to the
#   target's sources and its folder to the target's include directories.
include_guard(GLOBAL)

if(NOT MAX2CODE_COMMAND)
  message(FATAL_ERROR "max2code: MAX2CODE_COMMAND is not set; load this package with "
                      "find_package(max2code) and max2code_DIR=$(max2code runtime --cmake-dir)")
endif()

execute_process(COMMAND ${MAX2CODE_COMMAND} runtime --lang c --dir
                OUTPUT_VARIABLE MAX2CODE_C_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE _max2code_status ERROR_VARIABLE _max2code_error)
if(NOT _max2code_status EQUAL 0)
  message(FATAL_ERROR "max2code: '${MAX2CODE_COMMAND} runtime --lang c --dir' failed: "
                      "${_max2code_error}")
endif()

if(NOT TARGET max2code::runtime)
  enable_language(C)
  find_library(MAX2CODE_GSL_LIBRARY gsl REQUIRED)
  find_library(MAX2CODE_GSLCBLAS_LIBRARY gslcblas REQUIRED)
  find_path(MAX2CODE_GSL_INCLUDE_DIR gsl/gsl_poly.h REQUIRED)
  # (built only for a target that links it: a project that only generates code compiles nothing)
  add_library(max2code_runtime STATIC EXCLUDE_FROM_ALL "${MAX2CODE_C_RUNTIME}/max2code_roots.c")
  target_include_directories(max2code_runtime PUBLIC "${MAX2CODE_C_RUNTIME}"
                             PRIVATE "${MAX2CODE_GSL_INCLUDE_DIR}")
  target_link_libraries(max2code_runtime PUBLIC "${MAX2CODE_GSL_LIBRARY}"
                        "${MAX2CODE_GSLCBLAS_LIBRARY}" m)
  set_target_properties(max2code_runtime PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON
                        POSITION_INDEPENDENT_CODE ON)
  add_library(max2code::runtime ALIAS max2code_runtime)
endif()

function(max2code_generate out_var)
  cmake_parse_arguments(ARG "" "MXM;LANG;OUTPUT;TARGET" "OPTIONS" ${ARGN})
  if(NOT ARG_MXM)
    message(FATAL_ERROR "max2code_generate: MXM <file.mxm> is required")
  endif()
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "max2code_generate: unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_LANG)
    set(ARG_LANG c)
  endif()
  # (the registry's languages, from max2codeConfig.cmake; the four shipped ones otherwise)
  if(DEFINED MAX2CODE_LANGUAGE_EXTENSIONS)
    set(_extensions ${MAX2CODE_LANGUAGE_EXTENSIONS})
  else()
    set(_extensions c .h python .py rust .rs m2 .mod)
  endif()
  set(_names "")
  list(LENGTH _extensions _count)
  math(EXPR _last "${_count} - 1")
  set(_at -1)
  foreach(_k RANGE 0 ${_last} 2)
    list(GET _extensions ${_k} _name)
    list(APPEND _names ${_name})
    if(_name STREQUAL ARG_LANG)
      set(_at ${_k})
    endif()
  endforeach()
  if(_at EQUAL -1)
    string(REPLACE ";" ", " _names "${_names}")
    message(FATAL_ERROR "max2code_generate: LANG must be one of ${_names}")
  endif()
  math(EXPR _at "${_at} + 1")
  list(GET _extensions ${_at} _extension)
  get_filename_component(_mxm "${ARG_MXM}" ABSOLUTE)
  if(NOT ARG_OUTPUT)
    # Named as `max2code build` names it: after the declared function, else the file's stem.
    # Reading the header again when the .mxm changes keeps the name right after a rename.
    execute_process(COMMAND ${MAX2CODE_COMMAND} --lang=${ARG_LANG} --print-name "${_mxm}"
                    OUTPUT_VARIABLE _stem ERROR_VARIABLE _error RESULT_VARIABLE _status
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT _status EQUAL 0)
      message(FATAL_ERROR "max2code_generate: ${_error}")
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_mxm}")
    set(ARG_OUTPUT "${_stem}${_extension}")
  endif()
  set(_out "${CMAKE_CURRENT_BINARY_DIR}/${ARG_OUTPUT}")
  set(_outputs "${_out}")
  if(ARG_LANG STREQUAL "m2")
    string(REGEX REPLACE "\\.mod$" ".def" _def "${_out}")
    list(APPEND _outputs "${_def}")
  endif()
  add_custom_command(
    OUTPUT ${_outputs}
    COMMAND ${MAX2CODE_COMMAND} --lang=${ARG_LANG} "${_mxm}" -o "${_out}" -MF "${_out}.d"
            ${ARG_OPTIONS}
    DEPENDS "${_mxm}"
    DEPFILE "${_out}.d"
    COMMENT "max2code ${ARG_OUTPUT}"
    VERBATIM)
  if(ARG_TARGET)
    target_sources(${ARG_TARGET} PRIVATE "${_out}")
    target_include_directories(${ARG_TARGET} PRIVATE "${CMAKE_CURRENT_BINARY_DIR}")
  endif()
  set(${out_var} "${_out}" PARENT_SCOPE)
endfunction()
