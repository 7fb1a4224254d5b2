/* snapshot.h — particle snapshots (VTU, CSV), the ParaView collection (.pvd)
 * and generic CSV tables (summary.csv, measurements).
 *
 * Every file is written whole or not at all through atomic_file (see atomic_file.h); on
 * failure the previous file of that name is left as it was and err names the
 * file and the cause (code HV_EXIT_RUN). Snapshots hold the real particles
 * [0, p->n) only, never ghosts. Values are SI (m, kg, s, Pa, J/kg); the file
 * formats are described in docs/output-files.md.
 */
#ifndef HV_SNAPSHOT_H
#define HV_SNAPSHOT_H

#include "core/error.h"
#include "particles/particles.h"

struct snapshot_meta {
  double time;                       /* [s] simulated time of the snapshot */
  long step;                         /* step number */
  const char *version;               /* hvsph version string, written into every file */
  const char *case_name;             /* name of the case */
  const char *const *material_names; /* index -> name, for the mat column; may be NULL */
  int nmat;                          /* entries in material_names */
  const char *const *body_names;     /* index -> name, for the body column; may be NULL */
  int nbody;                         /* entries in body_names */
  int vtu_zlib;                      /* VTU: zlib-compressed arrays (output.compress) */
};

/* VTK XML UnstructuredGrid (.vtu), appended raw binary data with
 * header_type="UInt64" (no base64; zlib-compressed when meta->vtu_zlib): one
 * VTK_VERTEX cell per particle, Points = x, PointData = every other field flagged
 * PF_OUT (vectors as 3-component arrays named like the field, e.g. "v"; int64 ->
 * Int64, int32 -> Int32, double -> Float64), FieldData TIME [s], STEP, GEOMETRY (Int32 1
 * when p->axisym; absent for 3D) and the material and body names ("mat <name>",
 * "body <name>": Int32, the index). */
int io_write_vtu(const char *path, struct particles *p, const struct snapshot_meta *meta,
                 struct hv_error *err);

/* Particle CSV: a comment line "# hvsph <version> case <name> time <t> s step <k>",
 * optionally a "# materials ..." comment line, "# geometry: axisymmetric" when p->axisym,
 * then the header
 * id,x,y,z,vx,vy,vz,m,rho,p,e,h,mat followed by the other PF_OUT fields in list
 * order (vectors as name_x,name_y,name_z); values %.17g (round-trip exact). */
int io_write_particles_csv(const char *path, struct particles *p, const struct snapshot_meta *meta,
                           struct hv_error *err);

/* Reads a file written by io_write_particles_csv, appending its rows to p as
 * real particles (ghosts are dropped). Columns are matched by name; unknown
 * columns are ignored, missing known columns stay zero; a missing id, x, y or z
 * column is an error (HV_EXIT_INPUT). *time [s] gets the time from the comment
 * line, or NaN when there is none; time may be NULL. p->axisym is set from a
 * "# geometry:" comment before the header (axisymmetric or 3d; none: 3D), as
 * io_take_geometry in io_internal.h says (a file of the other geometry than the
 * particles already in p, or an axisymmetric one with r < 0 or z != 0, is refused). On
 * error p->n is restored. */
int io_read_particles_csv(const char *path, struct particles *p, double *time,
                          struct hv_error *err);

/* Reads a file written by io_write_vtu the same way: arrays matched by name against
 * the fields (positions from Points), unknown arrays ignored, missing fields zero;
 * *time [s] from FieldData TIME (NaN when absent), p->axisym from FieldData GEOMETRY as
 * for the CSV. Reads only hvsph's own form
 * (UInt64 headers, appended raw data in this machine's byte order, uncompressed or
 * compressed by vtkZLibDataCompressor); anything else,
 * a block whose byte count does not match NumberOfPoints, or a file cut short is an
 * error naming the file and the array (HV_EXIT_INPUT), and p->n is restored. */
int io_read_particles_vtu(const char *path, struct particles *p, double *time,
                          struct hv_error *err);

/* io_read_particles_vtu for a path ending in .vtu, io_read_particles_csv otherwise. */
int io_read_particles(const char *path, struct particles *p, double *time, struct hv_error *err);

/* The material names of a snapshot of either kind (its "materials 0=... 1=..." comment)
 * into names[index] (max entries); returns 1 + the largest index found, 0 if none. */
int io_read_material_names(const char *path, char names[][64], int max);

/* ParaView collection: rewrites the whole .pvd listing every (times[k] [s],
 * files[k]) so far, after an XML comment with meta's version and case name (meta may
 * be NULL; its time and step are not used). File names are written as given;
 * ParaView resolves them relative to the .pvd's folder. */
int io_write_pvd(const char *path, const double *times, const char *const *files, int n,
                 const struct snapshot_meta *meta, struct hv_error *err);

/* A generic CSV table: optional comment (each line prefixed "# "), a header of
 * the ncols column names, then nrows rows from rows[r * ncols + c]. A value that
 * is integral with |v| < 2^53 prints as an integer, any other as %.17g. */
int io_write_table_csv(const char *path, const char *const *cols, int ncols, const double *rows,
                       int nrows, const char *comment, struct hv_error *err);

/* Reading back a run's folder. io_read_table_column: the values of column `col` of a
 * table written by io_write_table_csv (e.g. summary.csv's "time"), in row order, into a
 * new array (the caller frees); returns the row count, or -1 (err, HV_EXIT_INPUT) when
 * the file cannot be read or has no such column. io_list_snapshots: the numbers NNNNN
 * of the files particles_NNNNN.<ext> in dir, sorted ascending, into a new array;
 * returns the count, or -1 when dir cannot be read. */
int io_read_table_column(const char *path, const char *col, double **vals, struct hv_error *err);
int io_list_snapshots(const char *dir, const char *ext, int **nums);
/* The snapshots a run folder can be re-read from: its particles_NNNNN.csv files when
 * it has any (the same values as its VTU files, and the form tools read), otherwise
 * its particles_NNNNN.vtu; *n as io_list_snapshots returns; returns the extension
 * ("csv" or "vtu"). */
const char *io_list_readable_snapshots(const char *dir, int **nums, int *n);

/* The (timestep [s], file) entries of a ParaView collection written by io_write_pvd, in
 * the file's order, into new arrays (the caller frees each files[k] and both arrays);
 * XML character entities in the names are decoded. Returns the count, or -1 (err,
 * HV_EXIT_INPUT, naming the file) when it cannot be read or is not a collection. */
int io_read_pvd(const char *path, double **times, char ***files, struct hv_error *err);

/* Whether snapshot number k, whose file gives the time t [s], is one of the outputs of
 * the run whose summary.csv lists the times times[0..nt): a run numbers its outputs 0, 1,
 * ... as the rows of its summary.csv, so k must be a row and t that row's time (to 1e-9,
 * relative). A folder reused by a shorter run keeps the earlier run's later snapshots;
 * they fail here. nt < 0 (no summary.csv): every snapshot is taken as the run's. */
int io_snapshot_in_run(int k, double t, const double *times, int nt);

/* A snapshot of a run folder: the file particles_NNNNN.<ext>. */
struct io_run_snapshot {
  int num;         /* NNNNN */
  const char *ext; /* "vtu" or "csv" (a string constant) */
};

/* The snapshots of the run whose output folder is dir, in the run's order, into a new
 * array (the caller frees): the entries of its run.pvd when it has one (the run rewrites
 * it at every output, so it lists this run's snapshots only, not those an earlier run
 * left in the folder), otherwise every particles_NNNNN.<prefer> of the folder, or when
 * there is none every one of the other kind, by number (a run with output.vtu: false;
 * an earlier run's are told from the run's own by io_snapshot_in_run once read). Each
 * entry's ext is `prefer` ("vtu" or "csv") where that file exists, else the other kind
 * where that one does, else `prefer` (reading it then says it is missing). Returns the
 * count (0: none), or -1 (err, HV_EXIT_INPUT) when the folder or its run.pvd cannot be
 * read, or run.pvd names a file that is not a particles_NNNNN.vtu of the folder. */
int io_run_snapshots(const char *dir, const char *prefer, struct io_run_snapshot **list,
                     struct hv_error *err);

#endif
