/* series.c — every snapshot of a run as the frames of a movie: `hvsph render RUNDIR -o
 * FRAMEDIR [options]`.
 *
 * The run's snapshots are those io_run_snapshots lists (run.pvd's entries, each the .vtu
 * file or, where only that exists, the .csv; without a run.pvd the folder's files) that
 * io_snapshot_in_run finds among the outputs of the run's summary.csv (as `hvsph measure`
 * does: a folder reused by a shorter run keeps the earlier run's later snapshots). Two
 * passes over them, one snapshot in memory at a time. The first reads each in turn and
 * gathers what must be the same in every frame, so that the picture does not jump:
 *   - mirroring: automatic means on when every snapshot is a half model;
 *   - without --box, the extent: the union of the extents each snapshot would get alone
 *     (its particles with their 2h supports and the 4 % margin); the picture's size
 *     follows from it, and an automatic height is made even (video encoders such as
 *     ffmpeg's yuv420p want even sizes);
 *   - particles mode coloured by a quantity without --range: the range over all of them;
 *   - the material colours: ranked by the first body of each material over all of them
 *     (a projectile whose particles have all left the domain does not pass its colour on).
 *   - the radiograph's μ, when --mu does not give it: the automatic choice
 *     (render_auto_mu) for the last snapshot in the common view, read once more after
 *     the first pass. The film, T = exp(−μσ), then maps areal density to grey the same
 *     way in every frame, and so does its wedge. The last snapshot, because an impact's
 *     material is thinnest late, when the debris has spread: exposed for it, the cloud
 *     stays visible to the end, and the earlier, denser frames are darker, as they
 *     would be on film.
 * The second pass reads each again and writes FRAMEDIR/frame_NNNNN.png (render_png:
 * a temporary file, then renamed), NNNNN = 0, 1, ... in the run's order: contiguous, as
 * ffmpeg's frame_%05d.png pattern wants, also where a snapshot is missing from the folder.
 */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "io/snapshot.h"
#include "render/render_internal.h"

/* A snapshot of the run, to become a frame. */
struct frame {
  int num;          /* its NNNNN */
  const char *ext;  /* "vtu" or "csv" */
};

static void snapshot_path(char *buf, size_t len, const char *dir, const struct frame *f)
{
  snprintf(buf, len, "%s/particles_%05d.%s", dir, f->num, f->ext);
}

/* The frame_NNNNN.png files in dir numbered n or higher (an earlier, longer series'). */
static int frames_beyond(const char *dir, int n)
{
  DIR *d = opendir(dir);
  if (!d) return 0;
  int count = 0, k, len;
  struct dirent *e;
  while ((e = readdir(d)))
    if (sscanf(e->d_name, "frame_%d%n", &k, &len) == 1 && !strcmp(e->d_name + len, ".png") &&
        k >= n)
      count++;
  closedir(d);
  return count;
}

/* Reads one snapshot into p (initialised, empty); an empty snapshot, or one holding
 * values that cannot be drawn (render_check_particles), is an error. */
static int load(const char *path, struct particles *p, double *t, struct hv_error *err)
{
  *t = NAN;
  if (io_read_particles(path, p, t, err)) return -1;
  if (p->n == 0) return hv_error_set(err, HV_EXIT_INPUT, "'%s' holds no particles", path);
  char names[RENDER_MAX_MATERIALS][64] = {{0}};
  return render_check_particles(p, io_read_material_names(path, names, RENDER_MAX_MATERIALS),
                                path, err);
}

int render_series(const char *rundir, const char *framedir, const struct render_options *opt,
                  struct hv_error *err)
{
  struct io_run_snapshot *snaps = NULL;
  const int ns = io_run_snapshots(rundir, "vtu", &snaps, err);
  if (ns < 0) return -1;
  if (ns == 0) {
    free(snaps);
    return hv_error_set(err, HV_EXIT_INPUT, "%s: no particle snapshots (particles_NNNNN.vtu or "
                        ".csv) in the run folder", rundir);
  }
  char path[4400], fpath[4400];
  double *times = NULL;
  struct hv_error ignored;
  snprintf(path, sizeof path, "%s/summary.csv", rundir);
  const int nt = io_read_table_column(path, "time", &times, &ignored);
  if (nt < 0) hv_warn("%s: every snapshot is taken as the run's", ignored.msg);

  struct render_options o = *opt;
  const int want_range = o.mode == RENDER_PARTICLES && o.color != RENDER_COLOR_MATERIAL &&
                         o.color != RENDER_COLOR_DAMAGE && !o.have_range;
  /* per mirroring (0 off, 1 on) while the automatic choice is not yet known */
  double ext[2][4], lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL};
  for (int m = 0; m < 2; m++) {
    ext[m][0] = ext[m][2] = HUGE_VAL;
    ext[m][1] = ext[m][3] = -HUGE_VAL;
  }
  int half = 1, nmat = 1, nf = 0, rc = 0, iu = 0, iv = 1;
  int *first = hv_malloc(RENDER_MATERIAL_CAP * sizeof *first, "material slots");
  int *slot = hv_malloc(RENDER_MATERIAL_CAP * sizeof *slot, "material slots");
  for (int m = 0; m < RENDER_MATERIAL_CAP; m++) first[m] = INT_MAX;
  struct frame *frames = hv_malloc((size_t)ns * sizeof *frames, "frames");
  struct particles p;

  /* pass 1: which snapshots, and what every frame shares */
  for (int j = 0; j < ns && !rc; j++) {
    const struct frame f = {snaps[j].num, snaps[j].ext};
    snapshot_path(path, sizeof path, rundir, &f);
    particles_init(&p);
    double t = NAN;
    int ours = nt < 0 || f.num < nt; /* a number beyond summary.csv's rows is not read */
    if (ours) rc = load(path, &p, &t, err);
    if (!rc && !(ours = io_snapshot_in_run(f.num, t, times, nt)))
      hv_warn("%s is not one of the outputs in summary.csv (an earlier run's, left in the "
              "folder): skipped", path);
    if (!rc && ours) {
      half = half && render_half_model(&p);
      for (int m = 0; m < 2 && !rc; m++) {
        if (o.mirror >= 0 && m != o.mirror) continue;
        struct render_options om = o;
        om.mirror = m;
        struct render_view v;
        if (render_view_setup(&p, &om, &v, err)) {
          rc = hv_error_prefix(err, "%s: ", path);
          break;
        }
        iu = v.iu;
        iv = v.iv;
        ext[m][0] = fmin(ext[m][0], v.ext[0]);
        ext[m][1] = fmax(ext[m][1], v.ext[1]);
        ext[m][2] = fmin(ext[m][2], v.ext[2]);
        ext[m][3] = fmax(ext[m][3], v.ext[3]);
        if (want_range) render_color_extend(&p, &v, &om, &lo[m], &hi[m]);
      }
      if (!rc) {
        for (size_t i = 0; i < p.n; i++)
          if (p.mat[i] >= nmat && p.mat[i] < RENDER_MATERIAL_CAP) nmat = p.mat[i] + 1;
        render_material_first_body(&p, RENDER_MATERIAL_CAP, first);
        frames[nf++] = f;
      }
    }
    particles_free(&p);
  }
  if (!rc && nf == 0)
    rc = hv_error_set(err, HV_EXIT_INPUT, "%s: none of the snapshots is one of the outputs in "
                      "the run's summary.csv", rundir);
  if (!rc) {
    const int m = o.mirror >= 0 ? o.mirror : half;
    o.mirror = m;
    if (!o.have_box) { /* the union; the slab along the line of sight: everything */
      o.box[2 * o.axis] = -HUGE_VAL;
      o.box[2 * o.axis + 1] = HUGE_VAL;
      o.box[2 * iu] = ext[m][0];
      o.box[2 * iu + 1] = ext[m][1];
      o.box[2 * iv] = ext[m][2];
      o.box[2 * iv + 1] = ext[m][3];
      o.have_box = 1;
    }
    if (want_range) {
      render_color_limits(&o, &lo[m], &hi[m]);
      o.range[0] = lo[m];
      o.range[1] = hi[m];
      o.have_range = 1;
    }
    render_material_rank(first, nmat, slot);
    if (o.height <= 0) { /* the automatic height from the common extent, made even */
      struct render_view v;
      particles_init(&p); /* with the box and the mirroring given, the view needs no particle */
      rc = render_view_setup(&p, &o, &v, err);
      particles_free(&p);
      if (!rc) {
        o.width = v.width;
        o.height = v.height + v.height % 2;
      }
    }
  }
  if (!rc && o.mode == RENDER_RADIOGRAPH && !(o.mu > 0.0)) {  /* μ for every frame */
    double t;
    snapshot_path(path, sizeof path, rundir, &frames[nf - 1]);
    particles_init(&p);
    struct render_view v;
    rc = load(path, &p, &t, err) || render_view_setup(&p, &o, &v, err);
    if (!rc) {
      const size_t npix = (size_t)v.nu * (size_t)v.nv;
      double *sigma = hv_malloc(npix * sizeof *sigma, "areal density picture"), quartile;
      render_areal_density(&p, &v, sigma);
      unsigned char *occ = hv_malloc(npix, "occupied pixels");
      render_occupied(&p, &v, occ);
      o.mu = render_auto_mu(sigma, occ, npix, &quartile);
      free(occ);
      free(sigma);
      hv_info("film mu = %.3g m2/kg for every frame (the lower quartile of the areal "
              "densities of the material in %s, %.3g kg/m2, at T = 1/2)", o.mu, path, quartile);
    }
    particles_free(&p);
  }
  static char bnames[RENDER_MAX_BODIES][64];
  const char *bptr[RENDER_MAX_BODIES];
  const int nb = o.labels ? render_read_body_names(rundir, bnames, RENDER_MAX_BODIES) : 0;
  for (int k = 0; k < nb; k++) bptr[k] = bnames[k];
  if (!rc) rc = io_mkdir_p(framedir, err);

  /* pass 2: the frames */
  int written = 0;
  for (int j = 0; j < nf && !rc; j++) {
    double t;
    snapshot_path(path, sizeof path, rundir, &frames[j]);
    snprintf(fpath, sizeof fpath, "%s/frame_%05d.png", framedir, j);
    particles_init(&p);
    rc = load(path, &p, &t, err);
    if (!rc) {
      char names[RENDER_MAX_MATERIALS][64] = {{0}};
      const char *ptr[RENDER_MAX_MATERIALS];
      const int nm = io_read_material_names(path, names, RENDER_MAX_MATERIALS);
      for (int k = 0; k < RENDER_MAX_MATERIALS; k++) ptr[k] = names[k][0] ? names[k] : NULL;
      const struct render_info info = {.time = t, .material_names = ptr, .nmat = nm,
                                       .source = path, .material_slot = slot, .nslot = nmat,
                                       .body_names = bptr, .nbody = nb};
      rc = render_png(fpath, &p, &o, &info, err);
      /* a failure to write names the frame; one that does not is about the snapshot */
      if (rc && !strstr(err->msg, fpath)) hv_error_prefix(err, "%s: ", path);
      if (!rc) {
        written++;
        hv_info("wrote %s (%s, t = %g s, %zu particles)", fpath, path, t, p.n);
      }
    }
    particles_free(&p);
  }
  if (!rc) {
    const int stale = frames_beyond(framedir, written);
    if (stale > 0)
      hv_warn("%s also holds %d frame_NNNNN.png of an earlier, longer series (from "
              "frame_%05d.png on): remove them before making a movie of this one", framedir,
              stale, written);
    hv_info("%d frame%s of %s in %s (%dx%d pixels); a movie: ffmpeg -framerate 10 -i "
            "%s/frame_%%05d.png%s -pix_fmt yuv420p movie.mp4", written, written == 1 ? "" : "s",
            rundir, framedir, o.width, o.height, framedir,
            o.width % 2 || o.height % 2 ? " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'" : "");
  }
  free(frames);
  free(first);
  free(slot);
  free(snaps);
  free(times);
  return rc;
}
