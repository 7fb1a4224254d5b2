/* runfolder.h — a run folder's lock, and what an earlier run left in it.
 *
 * The lock: RUNDIR/.hvsph.lock, held with a POSIX record lock (fcntl F_SETLK on the
 * whole file) by the one process that writes the folder (hvsph run, restart, measure,
 * and validate on its DIR and on each case's folder). The kernel drops a record lock
 * when its process ends, however it ends, so a lock can never be held by a process
 * that is gone: a lock file that can be locked is free, whatever it says. The file
 * names its holder (pid, host, start time, command) for the message of a process that
 * finds it held; the holder removes it when done (unlink, then close, while still
 * holding the lock), so a lock file found at the start was left by a process that was
 * killed (SIGKILL, a crash, the machine going down): it is taken over with a note.
 * Record locks work across hosts on NFS (lockd); where the file system cannot lock at
 * all, hvsph warns and goes on unlocked.
 *
 * Record locks belong to the process, not to the descriptor: closing any descriptor of
 * the lock file in the holding process releases it, so nothing but runfolder_lock and
 * runfolder_unlock opens it.
 *
 * An earlier run: the files hvsph run writes (runfolder_is_run_file). hvsph run refuses
 * a folder that holds any of them unless --overwrite, which removes them first.
 */
#ifndef HV_RUNFOLDER_H
#define HV_RUNFOLDER_H

#include "core/error.h"

#define RUNFOLDER_LOCK ".hvsph.lock"

struct runfolder_lock {
  int fd;     /* -1: not held */
  int locked; /* 1: the record lock is held (0: held without, where unsupported) */
  char path[4200];
};

/* An unheld lock (fd = -1), safe to unlock. */
void runfolder_lock_init(struct runfolder_lock *l);
/* Takes the lock of folder dir (which must exist) for `what` ("run", "restart", ...).
 * Held by another process: HV_EXIT_INPUT naming the folder and the holder's pid, host
 * and start time. A lock file left by a process that is gone is taken over, with a note
 * unless quiet. */
int runfolder_lock(struct runfolder_lock *l, const char *dir, const char *what, int quiet,
                   struct hv_error *err);
/* Removes the lock file and releases the lock; harmless when not held. */
void runfolder_unlock(struct runfolder_lock *l);

/* Whether a file name is one that hvsph run writes into its folder: checkpoint.hvc,
 * used_parameters.yaml, summary.csv, run.pvd, run_segments.csv, measurements.csv,
 * particles_NNNNN.vtu/.csv, fragments_NNNNN.csv. */
int runfolder_is_run_file(const char *name);
/* What an earlier run left in dir, for a message ("checkpoint.hvc, summary.csv, 12
 * particle snapshots"); returns the number of its files (0: none, or no folder). */
int runfolder_earlier_run(const char *dir, char *what, size_t len);
/* Removes the earlier run's files from dir (and nothing else); returns how many, or -1
 * with err (HV_EXIT_INPUT) naming the file that could not be removed. */
int runfolder_remove_run(const char *dir, struct hv_error *err);

#endif
