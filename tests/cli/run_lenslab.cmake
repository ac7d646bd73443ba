# Runs the lenslab binary once and checks what a user would see: the exit code, the message
# on stderr, what appears on stdout and whether an output file was written.
#
#   cmake -DLENSLAB=<binary> -DARGS=<arg|arg|...> [checks] -P run_lenslab.cmake
#
# ARGS separates arguments with '|' (a ';' would split the add_test command line).
# Checks, each optional:
#   EXPECT_EXIT=zero|nonzero|<n>   exit code (default: zero)
#   STDERR_LINE=<text>             stderr is exactly this one line
#   STDERR_PREFIX=<text>           stderr is one line that starts with this text
#   STDERR_CONTAINS=<text>         stderr contains this text
#   STDOUT_CONTAINS=<text>         stdout contains this text
#   STDOUT_JSON=ON                 stdout is one valid JSON document
#   JSON_EVENT=<text>              ...whose tree.event is this and tree.children[0].event exists
#   JSON_KEYS=<key,key,...>        ...which has these top-level keys
#   OUTPUT=<path>                  removed before the run, then checked:
#   OUTPUT_CREATED=ON|OFF          the run must (ON, and it must be a PNG) or must not create it
#   OUTPUT_STARTS=<text>           ...a created output starts with this text instead (e.g. <svg)
#   MAKE_FILE=<path>               a regular file made before the run (its folder too), which
#                                  the run must leave as it was
#   MAKE_FILE_READ_ONLY=ON         ...with no write permission bit (chmod 444)
#   MAKE_LINK=<path>               a symbolic link made before the run, to LINK_TO, which must
#   LINK_TO=<target>               still be a link afterwards

cmake_minimum_required(VERSION 3.25)

if(NOT LENSLAB OR NOT DEFINED ARGS)
    message(FATAL_ERROR "run_lenslab.cmake: LENSLAB and ARGS are required")
endif()
if(NOT DEFINED EXPECT_EXIT)
    set(EXPECT_EXIT zero)
endif()
string(REPLACE "|" ";" arg_list "${ARGS}")

if(DEFINED OUTPUT)
    file(REMOVE "${OUTPUT}")
    get_filename_component(output_dir "${OUTPUT}" DIRECTORY)
    file(MAKE_DIRECTORY "${output_dir}")
endif()

set(made_file_text "lenslab test: this file must be left as it was\n")
if(DEFINED MAKE_FILE)
    file(REMOVE "${MAKE_FILE}")
    file(WRITE "${MAKE_FILE}" "${made_file_text}")
    if(MAKE_FILE_READ_ONLY)
        file(CHMOD "${MAKE_FILE}" PERMISSIONS OWNER_READ GROUP_READ WORLD_READ)
    endif()
endif()
if(DEFINED MAKE_LINK)
    get_filename_component(link_dir "${MAKE_LINK}" DIRECTORY)
    file(MAKE_DIRECTORY "${link_dir}")
    file(REMOVE "${MAKE_LINK}")
    file(CREATE_LINK "${LINK_TO}" "${MAKE_LINK}" SYMBOLIC)
endif()

execute_process(
    COMMAND "${LENSLAB}" ${arg_list}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err
    TIMEOUT 120)

set(failures "")
macro(fail what)
    string(APPEND failures "  - ${what}\n")
endmacro()

# Exit code. A crash or timeout makes rc a string ("Segmentation fault", "Process terminated
# due to timeout"): never a pass, whatever was expected.
if(NOT rc MATCHES "^[0-9]+$")
    fail("did not exit normally: ${rc}")
elseif(EXPECT_EXIT STREQUAL "zero")
    if(NOT rc EQUAL 0)
        fail("exit code ${rc}, expected 0")
    endif()
elseif(EXPECT_EXIT STREQUAL "nonzero")
    if(rc EQUAL 0)
        fail("exit code 0, expected a failure")
    endif()
elseif(NOT rc EQUAL EXPECT_EXIT)
    fail("exit code ${rc}, expected ${EXPECT_EXIT}")
endif()

# stderr: one line (trailing newline aside).
string(REGEX REPLACE "\n$" "" err_trimmed "${err}")
if(DEFINED STDERR_LINE OR DEFINED STDERR_PREFIX)
    if(err_trimmed MATCHES "\n")
        fail("stderr has more than one line")
    endif()
endif()
if(DEFINED STDERR_LINE AND NOT err_trimmed STREQUAL STDERR_LINE)
    fail("stderr is not the expected line\n      expected: ${STDERR_LINE}\n      got:      ${err_trimmed}")
endif()
if(DEFINED STDERR_PREFIX)
    string(FIND "${err_trimmed}" "${STDERR_PREFIX}" at)
    if(NOT at EQUAL 0)
        fail("stderr does not start with: ${STDERR_PREFIX}")
    endif()
endif()
if(DEFINED STDERR_CONTAINS)
    string(FIND "${err}" "${STDERR_CONTAINS}" at)
    if(at EQUAL -1)
        fail("stderr does not contain: ${STDERR_CONTAINS}")
    endif()
endif()

if(DEFINED STDOUT_CONTAINS)
    string(FIND "${out}" "${STDOUT_CONTAINS}" at)
    if(at EQUAL -1)
        fail("stdout does not contain: ${STDOUT_CONTAINS}")
    endif()
endif()
if(STDOUT_JSON)
    string(JSON root_type ERROR_VARIABLE json_error TYPE "${out}")
    if(json_error)
        fail("stdout is not valid JSON: ${json_error}")
    elseif(NOT root_type STREQUAL "OBJECT")
        fail("stdout is JSON ${root_type}, expected an object")
    elseif(DEFINED JSON_EVENT)
        string(JSON root_event ERROR_VARIABLE json_error GET "${out}" tree event)
        if(json_error OR NOT root_event STREQUAL JSON_EVENT)
            fail("tree.event is '${root_event}' ${json_error}, expected '${JSON_EVENT}'")
        endif()
        string(JSON first_event ERROR_VARIABLE json_error GET "${out}" tree children 0 event)
        if(json_error)
            fail("tree.children[0].event missing: ${json_error}")
        endif()
    endif()
    if(DEFINED JSON_KEYS AND NOT json_error)
        string(REPLACE "," ";" keys "${JSON_KEYS}")
        foreach(key IN LISTS keys)
            string(JSON value ERROR_VARIABLE key_error GET "${out}" "${key}")
            if(key_error)
                fail("JSON key '${key}' missing")
            endif()
        endforeach()
    endif()
endif()

if(DEFINED OUTPUT AND DEFINED OUTPUT_CREATED)
    if(OUTPUT_CREATED)
        if(NOT EXISTS "${OUTPUT}")
            fail("${OUTPUT} was not created")
        elseif(DEFINED OUTPUT_STARTS)
            file(READ "${OUTPUT}" head)
            string(FIND "${head}" "${OUTPUT_STARTS}" at)
            if(NOT at EQUAL 0)
                fail("${OUTPUT} does not start with ${OUTPUT_STARTS}")
            endif()
        else()
            file(READ "${OUTPUT}" magic LIMIT 8 HEX)
            if(NOT magic STREQUAL "89504e470d0a1a0a")
                fail("${OUTPUT} is not a PNG file (starts with ${magic})")
            endif()
        endif()
    elseif(EXISTS "${OUTPUT}")
        fail("${OUTPUT} was created although the command failed")
    endif()
    file(REMOVE "${OUTPUT}")
endif()

if(DEFINED MAKE_FILE)
    if(IS_DIRECTORY "${MAKE_FILE}" OR NOT EXISTS "${MAKE_FILE}")
        fail("${MAKE_FILE} is no longer the file made before the run")
    else()
        file(READ "${MAKE_FILE}" made_file_now)
        if(NOT made_file_now STREQUAL made_file_text)
            fail("${MAKE_FILE} was changed")
        endif()
    endif()
    file(REMOVE "${MAKE_FILE}")
endif()
if(DEFINED MAKE_LINK)
    if(NOT IS_SYMLINK "${MAKE_LINK}")
        fail("${MAKE_LINK} is no longer a symbolic link")
    endif()
    file(REMOVE "${MAKE_LINK}")
endif()

if(failures)
    string(REPLACE "|" " " shown "${ARGS}")
    message(FATAL_ERROR "lenslab ${shown}\n${failures}"
                        "exit: ${rc}\nstdout:\n${out}\nstderr:\n${err}")
endif()
