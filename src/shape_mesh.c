/* shape_mesh.c: mesh and mesh2 (and mesh files), kept once in scene.meshes
 * however often they are placed; eval_object.c parses them, lower.c lowers the
 * triangles once into a BVH of their own and each placement into an instance. */
#include <math.h>

#include "lower.h"
#include "shape.h"

void shape_trace_triangle(const double *a, const double *b, const double *c, const double *const *nrm,
                          const double o[3], const double d[3], double tmin, shape_hit *h);

static void bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	const scene_mesh *m = &s->meshes[o->mesh];
	double w[3];
	for (int v = 0; v < m->n_v; v++) {
		scene_xform_point(&o->xf, m->v[v], w);
		shape_grow_box(lo, hi, w);
	}
}

/* Face by face: a scene calls trace() a few thousand times at most, so no BVH. */
static void trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                  shape_hit *h)
{
	const scene_mesh *m = &s->meshes[o->mesh];
	for (int f = 0; f < m->n_faces; f++) {
		const int *vi = m->face[f];
		const double *nrm[3] = { NULL, NULL, NULL };
		if (m->n_nrm > 0)
			for (int k = 0; k < 3; k++)
				nrm[k] = m->nrm[m->face_nrm ? m->face_nrm[f][k] : vi[k]];
		shape_trace_triangle(m->v[vi[0]], m->v[vi[1]], m->v[vi[2]], nrm, ro, rd, tmin, h);
	}
}

int shape_mesh_inside_dir(const scene *s, const scene_object *o, double d[3])
{
	if (o->mesh < 0)
		return -1;
	if (o->shape == SHAPE_HEIGHT_FIELD) {   /* POV-Ray's: below its surface, over its square */
		d[0] = d[2] = 0;
		d[1] = 1;
		return 0;
	}
	const scene_mesh *m = &s->meshes[o->mesh];
	xform inv;
	if (o->shape != SHAPE_MESH || !m->has_inside_vector || lower_invert(&o->xf, &inv))
		return -1;
	/* POV-Ray's inside_vector is not moved with the mesh: a world direction */
	scene_xform_vector(&inv, m->inside_vector, d);
	return d[0] != 0 || d[1] != 0 || d[2] != 0 ? 0 : -1;
}

int shape_mesh_crossings(const scene *s, const scene_object *o, const double p[3], const double d[3])
{
	int n = 0;
	double t = 0;
	for (int c = 0; c < 256; c++) {   /* the nearest hit past the last, as kernels/csg_mesh.cl counts them */
		shape_hit h = { .t = INFINITY };
		shape_mesh.trace(s, o, p, d, t, &h);
		if (h.t == INFINITY)
			return n;
		n++;
		t = h.t;
	}
	return n;   /* CSG_CROSSINGS, where the kernels stop too */
}

/* POV-Ray's Mesh::Inside: an odd number of crossings along its inside_vector. */
static bool inside(const scene *s, const scene_object *o, const double p[3])
{
	double d[3];
	return shape_mesh_inside_dir(s, o, d) == 0 && shape_mesh_crossings(s, o, p, d) % 2 == 1;
}

static void dump(FILE *out, const scene_object *o)
{
	fprintf(out, "mesh %d", o->mesh);
	scene_dump_xform(out, &o->xf);
}

const shape_class shape_mesh = {
	.name = "mesh", .args = "", .needs = "triangles",
	.bounds = bounds, .trace = trace, .inside = inside, .lower = lower_mesh_instance, .dump = dump,
};
