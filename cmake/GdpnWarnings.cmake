# gdpn_warnings(target): the project's warning set; errors when GDPN_WERROR is on.
function(gdpn_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
    -Wconversion -Wsign-conversion -Wnull-dereference -Wdouble-promotion)
  if(GDPN_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# gdpn_module(name sources...): one library target gdpn_<name> with alias gdpn::<name>.
function(gdpn_module name)
  add_library(gdpn_${name} STATIC ${ARGN})
  add_library(gdpn::${name} ALIAS gdpn_${name})
  target_include_directories(gdpn_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>)
  set_target_properties(gdpn_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  gdpn_warnings(gdpn_${name})
endfunction()
