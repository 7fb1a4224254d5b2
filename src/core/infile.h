/* infile.h — opening a file that hvsph reads as input (case file, material library, EOS
 * table, checkpoint, particle snapshot): only a regular file, of bounded size.
 *
 * A FIFO named as a case file or checkpoint blocked fopen() for ever (no writer ever
 * comes), and `hvsph run /dev/zero` read until the kernel killed it (23 GiB). So the
 * path is stat()ed first and refused unless it is a regular file (a directory, FIFO,
 * socket or device is named as such); it is then opened with O_NONBLOCK, which does not
 * wait for a FIFO's writer, and fstat()ed again, so that a file replaced between the two
 * calls is refused too. A file larger than the caller's limit is refused before a byte
 * of it is read. Errors carry HV_EXIT_INPUT and name what the file is for and its path.
 */
#ifndef HV_INFILE_H
#define HV_INFILE_H

#include <stdio.h>

#include "core/error.h"

/* Opens `path` for reading (binary) as the `what` ("case file", "EOS table"...; NULL:
 * messages name the path alone, "cannot open 'x.vtu': ...");
 * max_bytes > 0 bounds its size. Returns the stream, with *size (may be NULL) set to the
 * file's size in bytes, or NULL with err set. */
FILE *hv_open_input(const char *path, const char *what, long long max_bytes, long long *size,
                    struct hv_error *err);

#endif
