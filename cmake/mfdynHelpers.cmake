# mfdyn_library(<name> SOURCES ... DEPENDS ...): a shared toolkit library libmfdyn<Name>.so,
# exported as mfdyn::<name>, with its headers reachable as "<name>/Header.hpp".
function(mfdyn_library name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
    set(target mfdyn_${name})
    if(NOT ARG_SOURCES)
        # A library folder still being written: an interface placeholder keeps the tree configurable.
        add_library(${target} INTERFACE)
        add_library(mfdyn::${name} ALIAS ${target})
        target_link_libraries(${target} INTERFACE ${ARG_DEPENDS})
        install(TARGETS ${target} EXPORT mfdynTargets)
        return()
    endif()
    add_library(${target} SHARED ${ARG_SOURCES})
    set_target_properties(${target} PROPERTIES OUTPUT_NAME mfdyn_${name} EXPORT_NAME ${name})
    add_library(mfdyn::${name} ALIAS ${target})
    target_include_directories(${target} PUBLIC
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/libraries>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/mfdyn>)
    target_compile_options(${target} PRIVATE -Wall -Wextra)
    target_link_libraries(${target} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
    install(TARGETS ${target} EXPORT mfdynTargets LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mfdyn/${name}
        FILES_MATCHING PATTERN "*.hpp")
endfunction()

# mfdyn_application(<name> SOURCES ... DEPENDS ...)
function(mfdyn_application name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
    add_executable(${name} ${ARG_SOURCES})
    target_compile_options(${name} PRIVATE -Wall -Wextra)
    target_link_libraries(${name} PRIVATE ${ARG_DEPENDS})
    # Executables export their symbols so that user libraries loaded with dlopen bind to
    # the registries already in the process.
    set_target_properties(${name} PROPERTIES ENABLE_EXPORTS ON)
    install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
