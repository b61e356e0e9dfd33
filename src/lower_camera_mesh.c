/* lower_camera_mesh.c: the mesh_camera's rays, made once on the host for the
 * image's size, as POV-Ray 3.7's TracePixel::CreateCameraRay makes them. Two
 * float4 per pixel and ray number r, at ((r * height + y) * width + x) * 2:
 * the origin (w 1, or 0 where the camera makes no ray) and the direction (w:
 * the maximum distance, 0 for none). kernels/camera_mesh.cl reads them.
 *
 * POV-Ray's quirks are kept, since its images are the reference: distribution
 * 1 offsets ray r by r times the faces (not the pixels), so only ray 0 ever
 * finds a face; distribution 2 numbers a face from the image's left edge in
 * every view, not from the view's own. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diag.h"
#include "lower.h"

/* A face's corners, normals (its flat one thrice unless smooth) and uv. */
struct face {
	double p[3][3], n[3][3], uv[3][2];
};

static void sub(const double a[3], const double b[3], double o[3])
{
	for (int k = 0; k < 3; k++)
		o[k] = a[k] - b[k];
}

/* Face f's uv at its corners; POV-Ray's are 0 without uv_vectors. */
static void face_uv(const scene_mesh *m, int f, double uv[3][2])
{
	for (int c = 0; c < 3; c++) {
		uv[c][0] = uv[c][1] = 0;
		if (m->face_uv)
			memcpy(uv[c], m->uv[m->face_uv[f][c]], sizeof uv[c]);
	}
}

static void get_face(const scene_mesh *m, int f, bool smooth, struct face *out)
{
	face_uv(m, f, out->uv);
	for (int c = 0; c < 3; c++)
		memcpy(out->p[c], m->v[m->face[f][c]], sizeof out->p[c]);
	/* POV-Ray's face normal: (P3 - P1) x (P2 - P1), unit */
	double a[3], b[3], n[3];
	sub(out->p[2], out->p[0], a);
	sub(out->p[1], out->p[0], b);
	n[0] = a[1] * b[2] - a[2] * b[1];
	n[1] = a[2] * b[0] - a[0] * b[2];
	n[2] = a[0] * b[1] - a[1] * b[0];
	double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
	for (int c = 0; c < 3; c++)
		for (int k = 0; k < 3; k++)
			out->n[c][k] = smooth && m->face_nrm ? m->nrm[m->face_nrm[f][c]][k] : l > 0 ? n[k] / l : 0;
}

/* The ray from barycentric point w of face f, moved by location.z along its
 * direction, turned over when direction.z < 0, then placed by the mesh's
 * transformation (the direction as a normal). */
static void face_ray(const scene_camera *c, const scene_camera_mesh *cm, const xform *inv, const struct face *f,
                     const double w[3], float4 out[2])
{
	double o[3] = { 0, 0, 0 }, d[3] = { 0, 0, 0 }, wo[3], wd[3];
	for (int v = 0; v < 3; v++)
		for (int k = 0; k < 3; k++) {
			o[k] += w[v] * f->p[v][k];
			d[k] += w[v] * f->n[v][k];
		}
	for (int k = 0; k < 3; k++)
		o[k] += c->location[2] * d[k];
	if (c->direction[2] < -1e-10)
		for (int k = 0; k < 3; k++)
			d[k] = -d[k];
	scene_xform_point(&cm->xf, o, wo);
	for (int k = 0; k < 3; k++)   /* the inverse transpose */
		wd[k] = inv->m[0][k] * d[0] + inv->m[1][k] * d[1] + inv->m[2][k] * d[2];
	out[0] = (float4){ (float)wo[0], (float)wo[1], (float)wo[2], 1 };
	out[1] = (float4){ (float)wd[0], (float)wd[1], (float)wd[2], (float)c->mesh_max_distance };
}

/* The ray from face f's centroid. */
static void centroid_ray(const scene *s, const scene_camera *c, int mesh, int f, const xform *inv, float4 out[2])
{
	const scene_camera_mesh *cm = &s->camera_meshes[c->mesh_first + mesh];
	struct face fc;
	get_face(&s->meshes[cm->mesh], f, false, &fc);
	const double third[3] = { 1.0 / 3, 1.0 / 3, 1.0 / 3 };
	face_ray(c, cm, &inv[mesh], &fc, third, out);
}

/* Distributions 0 to 2: pixel (x, y)'s ray number r, or none. */
static void indexed_ray(const scene *s, const scene_camera *c, const xform *inv, int w, int x, int y, int r,
                        const long *ends, float4 out[2])
{
	long face = (long)y * w + x;
	int mesh = r;
	if (c->mesh_method == 1) {
		face += (long)r * ends[c->mesh_count - 1];
		for (mesh = 0; mesh < c->mesh_count && ends[mesh] <= face; mesh++)
			;
		if (mesh == c->mesh_count)
			return;
		face -= mesh ? ends[mesh - 1] : 0;
	} else if (c->mesh_method == 2) {
		double span = (double)w / c->mesh_count;
		mesh = (int)(x / span);
		if (mesh >= c->mesh_count)
			return;
		face = (long)y * (long)span + x;
	}
	if (face >= s->meshes[s->camera_meshes[c->mesh_first + mesh].mesh].n_faces)
		return;
	centroid_ray(s, c, mesh, (int)face, inv, out);
}

/* Distribution 3's index: a grid of cells over uv's unit square, each listing
 * in face order the faces whose uv box meets it, so that the first face found
 * holding a point is POV-Ray's (the lowest numbered). */
#define GRID 64
struct uv_grid {
	int *start;   /* GRID * GRID + 1 offsets into face */
	int *face;
};

static int cell(double t)
{
	int i = (int)floor(t * GRID);
	return i < 0 ? 0 : i >= GRID ? GRID - 1 : i;
}

static void face_cells(const scene_mesh *m, int f, int box[4])
{
	double uv[3][2];
	face_uv(m, f, uv);
	double lo[2] = { uv[0][0], uv[0][1] }, hi[2] = { lo[0], lo[1] };
	for (int v = 1; v < 3; v++)
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], uv[v][k]);
			hi[k] = fmax(hi[k], uv[v][k]);
		}
	box[0] = cell(lo[0]), box[1] = cell(lo[1]), box[2] = cell(hi[0]), box[3] = cell(hi[1]);
	if (!(hi[0] >= 0 && hi[1] >= 0 && lo[0] <= 1 && lo[1] <= 1))
		box[2] = box[0] - 1;   /* outside the square (or NaN): in no cell */
}

static int grid_build(const scene_mesh *m, struct uv_grid *g)
{
	g->start = calloc(GRID * GRID + 1, sizeof *g->start);
	long total = 0;
	for (int pass = 0; pass < 2 && g->start; pass++) {
		if (pass == 1) {
			for (int i = 0; i < GRID * GRID; i++)
				g->start[i + 1] += g->start[i];
			total = g->start[GRID * GRID];
			if (total > 200000000 || !(g->face = malloc((total ? total : 1) * sizeof *g->face)))
				return -1;
		}
		for (int f = 0; f < m->n_faces; f++) {
			int b[4];
			face_cells(m, f, b);
			for (int v = b[1]; v <= b[3]; v++)
				for (int u = b[0]; u <= b[2]; u++) {
					if (pass == 0)
						g->start[v * GRID + u + 1]++;
					else
						g->face[g->start[v * GRID + u]++] = f;
				}
		}
	}
	if (!g->start)
		return -1;
	for (int i = GRID * GRID; i > 0; i--)   /* the fill moved each start to its end */
		g->start[i] = g->start[i - 1];
	g->start[0] = 0;
	return 0;
}

/* Distribution 3: the ray from the first face whose uv triangle holds (u, v). */
static void uv_ray(const scene *s, const scene_camera *c, const xform *inv, const struct uv_grid *g, double u,
                   double v, float4 out[2])
{
	const scene_camera_mesh *cm = &s->camera_meshes[c->mesh_first];
	const scene_mesh *m = &s->meshes[cm->mesh];
	int at = cell(v) * GRID + cell(u);
	for (int i = g->start[at]; i < g->start[at + 1]; i++) {
		double t[3][2];   /* the whole face only for the one that holds (u, v) */
		face_uv(m, g->face[i], t);
		double scale = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
		double w[3] = { ((t[1][0] - u) * (t[2][1] - v) - (t[2][0] - u) * (t[1][1] - v)) / scale,
		                ((t[2][0] - u) * (t[0][1] - v) - (t[0][0] - u) * (t[2][1] - v)) / scale,
		                ((t[0][0] - u) * (t[1][1] - v) - (t[1][0] - u) * (t[0][1] - v)) / scale };
		if (w[0] < 0 || w[1] < 0 || w[2] < 0)
			continue;
		struct face f;
		get_face(m, g->face[i], c->mesh_smooth, &f);
		face_ray(c, cm, inv, &f, w, out);
		return;
	}
}

int lower_camera_mesh(const scene *s, int width, int height, lower_result *out)
{
	const scene_camera *c = &s->camera;
	if (c->type != CAMERA_MESH)
		return 0;
	int rays = c->mesh_method >= 2 ? 1 : c->mesh_rays;
	size_t n = (size_t)rays * width * height * 2;
	if (width <= 0 || height <= 0 || n / 2 > 64u * 1024 * 1024) {
		diag_error(c->loc, "the mesh_camera cannot make %d rays for each of %d x %d pixels", rays, width, height);
		return -1;
	}
	xform *inv = calloc(c->mesh_count, sizeof *inv);
	long *ends = calloc(c->mesh_count, sizeof *ends);
	out->camera_rays = calloc(n, sizeof *out->camera_rays);
	struct uv_grid g = { 0 };
	int rc = inv && ends && out->camera_rays ? 0 : -1;
	if (rc)
		diag_error(c->loc, "out of memory for the mesh_camera's rays");
	for (int i = 0; rc == 0 && i < c->mesh_count; i++) {
		const scene_camera_mesh *cm = &s->camera_meshes[c->mesh_first + i];
		ends[i] = (i ? ends[i - 1] : 0) + s->meshes[cm->mesh].n_faces;
		if (lower_invert(&cm->xf, &inv[i])) {
			diag_error(c->loc, "a mesh of the mesh_camera is scaled to nothing");
			rc = -1;
		}
	}
	if (rc == 0 && c->mesh_method == 3 && grid_build(&s->meshes[s->camera_meshes[c->mesh_first].mesh], &g)) {
		diag_error(c->loc, "out of memory for the mesh_camera's index of faces");
		rc = -1;
	}
	for (int r = 0; rc == 0 && r < rays; r++)
		for (int y = 0; y < height; y++)
			for (int x = 0; x < width; x++) {
				float4 *o = &out->camera_rays[(((size_t)r * height + y) * width + x) * 2];
				if (c->mesh_method == 3)   /* the pixel's centre in uv, v upwards */
					uv_ray(s, c, inv, &g, (x + 0.5) / width, 1.0 - (y + 0.5) / height, o);
				else
					indexed_ray(s, c, inv, width, x, y, r, ends, o);
			}
	free(g.start);
	free(g.face);
	free(inv);
	free(ends);
	if (rc) {
		free(out->camera_rays);
		out->camera_rays = NULL;
		return -1;
	}
	out->n_camera_rays = (long)n;
	out->params.lens.w = (float)rays;
	return 0;
}
