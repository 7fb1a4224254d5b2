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
 * An axisymmetric run's snapshots (rings) are framed as render_png draws them: across the
 * axis, both halves unless --no-mirror (render_rz_halves), the radiograph's μ from the
 * last snapshot's revolved areal density (render_areal_density_rz).
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
  int num;         /* its NNNNN */
  const char *ext; /* "vtu" or "csv" */
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
  return render_check_particles(p, io_read_material_names(path, names, RENDER_MAX_MATERIALS), path,
                                err);
}

/* A series under way: what every frame shares, gathered over the run's snapshots. */
struct series {
  const char *rundir;
  double *times; /* summary.csv's output times, nt of them (nt < 0: none read) */
  int nt;
  struct render_options o; /* the options of every frame */
  int want_range;          /* a colour range from all the frames */
  /* per mirroring (0 off, 1 on) while the automatic choice is not yet known */
  double ext[2][4], lo[2], hi[2];
  int half, nmat, iu, iv;
  int rz;               /* the snapshots are axisymmetric: o is the view across the axis (axis z) */
  int *first, *slot;    /* per material: its first body; its colour slot */
  struct frame *frames; /* the snapshots that are outputs of the run, nf of them */
  int nf;
};

/* The first axisymmetric snapshot turns the series' options into those of the picture
 * across the axis (render_rz_options: axis z, --axis x refused, --axis y's box read with
 * up = its z range), keeping the mirroring asked for: then the halves. */
static int rz_options(struct series *s, const struct particles *p, struct hv_error *err)
{
  if (!p->axisym || s->rz) return 0;
  struct render_options orz;
  if (render_rz_options(&s->o, &orz, err)) return -1;
  orz.mirror = s->o.mirror;
  s->o = orz;
  s->rz = 1;
  return 0;
}

/* What a frame of p shows: p, or for an axisymmetric snapshot its rings in the plane of
 * the axis (both halves with mirror; q holds them, particles_free it), and the options
 * it is framed with (*o, the mirroring then made by the halves). */
static const struct particles *shown(const struct particles *p, struct render_options *o,
                                     struct particles *q)
{
  if (!p->axisym) {
    particles_init(q);
    return p;
  }
  render_rz_halves(p, o->mirror != 0, q); /* initialises q */
  o->mirror = 0;
  return q;
}

/* Pass 1 for one snapshot: whether it is one of the run's outputs, and its extent,
 * colour range, materials and half-model flag added to what the frames share. */
static int scan_snapshot(struct series *s, const struct frame *f, struct hv_error *err)
{
  char path[4400];
  struct particles p;
  snapshot_path(path, sizeof path, s->rundir, f);
  particles_init(&p);
  double t = NAN;
  int rc = 0;
  int ours = s->nt < 0 || f->num < s->nt; /* a number beyond summary.csv's rows is not read */
  if (ours) rc = load(path, &p, &t, err);
  if (!rc && !(ours = io_snapshot_in_run(f->num, t, s->times, s->nt)))
    hv_warn("%s is not one of the outputs in summary.csv (an earlier run's, left in the "
            "folder): skipped",
            path);
  if (!rc && ours && rz_options(s, &p, err)) rc = hv_error_prefix(err, "%s: ", path);
  if (!rc && ours) {
    s->half = s->half && render_half_model(&p);
    for (int m = 0; m < 2 && !rc; m++) {
      if (s->o.mirror >= 0 && m != s->o.mirror) continue;
      struct render_options om = s->o;
      om.mirror = m;
      struct render_view v;
      struct particles q;
      const struct particles *pts = shown(&p, &om, &q);
      if (render_view_setup(pts, &om, &v, err)) {
        particles_free(&q);
        rc = hv_error_prefix(err, "%s: ", path);
        break;
      }
      s->iu = v.iu;
      s->iv = v.iv;
      s->ext[m][0] = fmin(s->ext[m][0], v.ext[0]);
      s->ext[m][1] = fmax(s->ext[m][1], v.ext[1]);
      s->ext[m][2] = fmin(s->ext[m][2], v.ext[2]);
      s->ext[m][3] = fmax(s->ext[m][3], v.ext[3]);
      if (s->want_range) render_color_extend(pts, &v, &om, &s->lo[m], &s->hi[m]);
      particles_free(&q);
    }
    if (!rc) {
      for (size_t i = 0; i < p.n; i++)
        if (p.mat[i] >= s->nmat && p.mat[i] < RENDER_MATERIAL_CAP) s->nmat = p.mat[i] + 1;
      render_material_first_body(&p, RENDER_MATERIAL_CAP, s->first);
      s->frames[s->nf++] = *f;
    }
  }
  particles_free(&p);
  return rc;
}

/* After pass 1: the mirroring, the box (the union of the frames' extents), the colour
 * range, the material slots and the picture's size that every frame shares. */
static int share_frame(struct series *s, struct hv_error *err)
{
  struct render_options *o = &s->o;
  const int m = o->mirror >= 0 ? o->mirror : s->half;
  o->mirror = m;
  if (!o->have_box) { /* the union; the slab along the line of sight: everything */
    o->box[2 * o->axis] = -HUGE_VAL;
    o->box[2 * o->axis + 1] = HUGE_VAL;
    o->box[2 * s->iu] = s->ext[m][0];
    o->box[2 * s->iu + 1] = s->ext[m][1];
    o->box[2 * s->iv] = s->ext[m][2];
    o->box[2 * s->iv + 1] = s->ext[m][3];
    o->have_box = 1;
  }
  if (s->want_range) {
    render_color_limits(o, &s->lo[m], &s->hi[m]);
    o->range[0] = s->lo[m];
    o->range[1] = s->hi[m];
    o->have_range = 1;
  }
  render_material_rank(s->first, s->nmat, s->slot);
  int rc = 0;
  if (o->height <= 0) { /* the automatic height from the common extent, made even */
    struct render_view v;
    struct particles p;
    particles_init(&p); /* with the box and the mirroring given, the view needs no particle */
    rc = render_view_setup(&p, o, &v, err);
    particles_free(&p);
    if (!rc) {
      o->width = v.width;
      o->height = v.height + v.height % 2;
    }
  }
  return rc;
}

/* A radiograph's film μ for every frame, from the last frame (render_auto_mu). */
static int share_mu(struct series *s, struct hv_error *err)
{
  char path[4400];
  double t;
  struct particles p;
  snapshot_path(path, sizeof path, s->rundir, &s->frames[s->nf - 1]);
  particles_init(&p);
  struct render_view v;
  struct render_options o = s->o;
  struct particles q;
  particles_init(&q);
  const struct particles *pts = &p;
  int rc = load(path, &p, &t, err);
  if (!rc) {
    pts = shown(&p, &o, &q); /* rings: the halves frame it, the rings make σ */
    rc = render_view_setup(pts, &o, &v, err);
  }
  if (!rc) {
    const size_t npix = (size_t)v.nu * (size_t)v.nv;
    double *sigma = hv_malloc(npix * sizeof *sigma, "areal density picture"), quartile;
    if (p.axisym)
      render_areal_density_rz(&p, &v, sigma);
    else
      render_areal_density(&p, &v, sigma);
    unsigned char *occ = hv_malloc(npix, "occupied pixels");
    render_occupied(pts, &v, occ);
    s->o.mu = render_auto_mu(sigma, occ, npix, &quartile);
    free(occ);
    free(sigma);
    hv_info("film mu = %.3g m2/kg for every frame (the lower quartile of the areal "
            "densities of the material in %s, %.3g kg/m2, at T = 1/2)",
            s->o.mu, path, quartile);
  }
  particles_free(&q);
  particles_free(&p);
  return rc;
}

/* Pass 2: frame j of the series written as framedir/frame_NNNNN.png. */
static int write_frame(const struct series *s, int j, const char *framedir, const char *const *bptr,
                       int nb, struct hv_error *err)
{
  char path[4400], fpath[4400];
  double t;
  struct particles p;
  snapshot_path(path, sizeof path, s->rundir, &s->frames[j]);
  snprintf(fpath, sizeof fpath, "%s/frame_%05d.png", framedir, j);
  particles_init(&p);
  int rc = load(path, &p, &t, err);
  if (!rc) {
    char names[RENDER_MAX_MATERIALS][64] = {{0}};
    const char *ptr[RENDER_MAX_MATERIALS];
    const int nm = io_read_material_names(path, names, RENDER_MAX_MATERIALS);
    for (int k = 0; k < RENDER_MAX_MATERIALS; k++) ptr[k] = names[k][0] ? names[k] : NULL;
    const struct render_info info = {.time = t,
                                     .material_names = ptr,
                                     .nmat = nm,
                                     .source = path,
                                     .material_slot = s->slot,
                                     .nslot = s->nmat,
                                     .body_names = bptr,
                                     .nbody = nb};
    rc = render_png(fpath, &p, &s->o, &info, err);
    /* a failure to write names the frame; one that does not is about the snapshot */
    if (rc && !strstr(err->msg, fpath)) hv_error_prefix(err, "%s: ", path);
    if (!rc) hv_info("wrote %s (%s, t = %g s, %zu particles)", fpath, path, t, p.n);
  }
  particles_free(&p);
  return rc;
}

int render_series(const char *rundir, const char *framedir, const struct render_options *opt,
                  struct hv_error *err)
{
  struct io_run_snapshot *snaps = NULL;
  const int ns = io_run_snapshots(rundir, "vtu", &snaps, err);
  if (ns < 0) return -1;
  if (ns == 0) {
    free(snaps);
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: no particle snapshots (particles_NNNNN.vtu or "
                        ".csv) in the run folder",
                        rundir);
  }
  char path[4400];
  struct hv_error ignored;
  struct series s = {.rundir = rundir,
                     .o = *opt,
                     .lo = {HUGE_VAL, HUGE_VAL},
                     .hi = {-HUGE_VAL, -HUGE_VAL},
                     .half = 1,
                     .nmat = 1,
                     .iu = 0,
                     .iv = 1};
  snprintf(path, sizeof path, "%s/summary.csv", rundir);
  s.nt = io_read_table_column(path, "time", &s.times, &ignored);
  if (s.nt < 0) hv_warn("%s: every snapshot is taken as the run's", ignored.msg);
  s.want_range = s.o.mode == RENDER_PARTICLES && s.o.color != RENDER_COLOR_MATERIAL &&
                 s.o.color != RENDER_COLOR_DAMAGE && !s.o.have_range;
  for (int m = 0; m < 2; m++) {
    s.ext[m][0] = s.ext[m][2] = HUGE_VAL;
    s.ext[m][1] = s.ext[m][3] = -HUGE_VAL;
  }
  s.first = hv_malloc(RENDER_MATERIAL_CAP * sizeof *s.first, "material slots");
  s.slot = hv_malloc(RENDER_MATERIAL_CAP * sizeof *s.slot, "material slots");
  for (int m = 0; m < RENDER_MATERIAL_CAP; m++) s.first[m] = INT_MAX;
  s.frames = hv_malloc((size_t)ns * sizeof *s.frames, "frames");

  /* pass 1: which snapshots, and what every frame shares */
  int rc = 0;
  for (int j = 0; j < ns && !rc; j++) {
    const struct frame f = {snaps[j].num, snaps[j].ext};
    rc = scan_snapshot(&s, &f, err);
  }
  if (!rc && s.nf == 0)
    rc = hv_error_set(err, HV_EXIT_INPUT,
                      "%s: none of the snapshots is one of the outputs in "
                      "the run's summary.csv",
                      rundir);
  if (!rc) rc = share_frame(&s, err);
  if (!rc && s.o.mode == RENDER_RADIOGRAPH && !(s.o.mu > 0.0)) rc = share_mu(&s, err);
  static char bnames[RENDER_MAX_BODIES][64];
  const char *bptr[RENDER_MAX_BODIES];
  const int nb = s.o.labels ? render_read_body_names(rundir, bnames, RENDER_MAX_BODIES) : 0;
  for (int k = 0; k < nb; k++) bptr[k] = bnames[k];
  if (!rc) rc = io_mkdir_p(framedir, err);

  /* pass 2: the frames */
  int written = 0;
  for (int j = 0; j < s.nf && !rc; j++)
    if (!(rc = write_frame(&s, j, framedir, bptr, nb, err))) written++;
  if (!rc) {
    const int stale = frames_beyond(framedir, written);
    if (stale > 0)
      hv_warn("%s also holds %d frame_NNNNN.png of an earlier, longer series (from "
              "frame_%05d.png on): remove them before making a movie of this one",
              framedir, stale, written);
    hv_info("%d frame%s of %s in %s (%dx%d pixels); a movie: ffmpeg -framerate 10 -i "
            "%s/frame_%%05d.png%s -pix_fmt yuv420p movie.mp4",
            written, written == 1 ? "" : "s", rundir, framedir, s.o.width, s.o.height, framedir,
            s.o.width % 2 || s.o.height % 2 ? " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'" : "");
  }
  free(s.frames);
  free(s.first);
  free(s.slot);
  free(snaps);
  free(s.times);
  return rc;
}
