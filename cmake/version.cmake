# Writes the version header from `git describe` at every build (cmake -P, called by
# the hvsph_version target): configure_file rewrites it only when the text changes, so
# an unchanged version rebuilds nothing, and a new commit or an edit (-dirty) is never
# missed by a build directory configured earlier.
# In: SRC_DIR (the source tree), IN (version.h.in), OUT (the generated header).
# safe.directory: a checkout owned by another user (a mounted volume, a clone made as
# another user, built as root) is read too; git refuses it otherwise ("unknown").
execute_process(COMMAND git -c safe.directory=* describe --always --dirty --tags
                WORKING_DIRECTORY ${SRC_DIR}
                OUTPUT_VARIABLE HVSPH_GIT_VERSION OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET)
if(NOT HVSPH_GIT_VERSION)
  set(HVSPH_GIT_VERSION "unknown")
endif()
configure_file(${IN} ${OUT} @ONLY)
