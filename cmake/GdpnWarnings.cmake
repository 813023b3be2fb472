# gdpn_warnings(target): the project's warning set; errors when GDPN_WERROR is on.
function(gdpn_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
    -Wconversion -Wsign-conversion -Wdouble-promotion)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    # GCC 12 reports -Wrestrict inside std::string's operator+ at -O3 (GCC bug 105651)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(GDPN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# gdpn_kind_switches(target): a switch on an enum names every value (-Wswitch-enum), even
# where it has a default:, so that a new kind of node, sensor, formula or action is listed by
# the compiler wherever it must be handled. The libraries, the gdpn program and the Python
# module; tests and benchmarks may let a default: stand for "not this one".
function(gdpn_kind_switches target)
  target_compile_options(${target} PRIVATE -Wswitch-enum)
endfunction()

# gdpn_module(name sources...): one library target gdpn_<name> with alias gdpn::<name>. Only
# the public headers (include/) are on the include path: a module's private headers stay in
# its src/<name>/ folder and are included relative to the file that needs them, so no other
# module can reach them.
function(gdpn_module name)
  add_library(gdpn_${name} STATIC ${ARGN})
  add_library(gdpn::${name} ALIAS gdpn_${name})
  target_include_directories(gdpn_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>)
  set_target_properties(gdpn_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  gdpn_warnings(gdpn_${name})
  gdpn_kind_switches(gdpn_${name})
endfunction()
