# Writes OUT (qacc_version.h: #define QACC_GIT_VERSION "...") from `git describe` of SRC at
# every build, rewriting it only when the version changed (so nothing rebuilds otherwise).
execute_process(COMMAND git describe --always --dirty --abbrev=12 WORKING_DIRECTORY ${SRC}
                OUTPUT_VARIABLE v OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT v)
  set(v "unknown")
endif()
set(text "#define QACC_GIT_VERSION \"${v}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
