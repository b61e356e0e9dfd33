/* test_csg.c: CSG through the whole pipeline (the scene text parsed and
 * evaluated, lowered, and cast through kernels/raycast.cl) against a
 * reference written from POV-Ray's definitions, in double precision:
 *
 *   inside:  union and merge: inside any part; intersection: inside all;
 *            difference: inside the first and none of the others;
 *            inverse: the other way round;
 *   hits:    a union's are all its parts' hits; a merge keeps a part's hit
 *            outside every other part; an intersection keeps a part's hit
 *            inside every other part; a difference keeps the first part's
 *            hits outside the others, and another part's hits inside the
 *            first and outside the rest (POV-Ray's CSG::All_Intersections).
 *
 * The reference is a recursion over the tree; the kernels run a flat program
 * (kernels/csg.cl), so the two are independent. Each case is a CSG tree of
 * spheres and boxes, each operation alone and then random trees three levels
 * deep with inverses, then the same with meshes among the leaves (a box as a
 * closed mesh2 with inside_vector, inside by the parity of its crossings: the
 * box's inside; the box's mesh without one and a parametric square, with no
 * inside and only their nearest hit along a ray, as POV-Ray's mesh and
 * parametric give a CSG), then CSG objects of 50 to 140 leaves (spheres,
 * boxes and cylinders, three levels deep, some parts clipped_by a sphere),
 * whose hits come through the kernels' tree over the leaves' boxes and whose
 * classifications skip parts of the program where no leaf's box holds the
 * point (a traversal that loses a subtree, or a skip taken wrongly, fails
 * them), and one ok/FAIL line a case: every closest hit of its
 * rays agrees, except rays whose reference hit lies within a hair of another
 * leaf's surface or grazes one, where single precision may go either way,
 * and the host's inside (each leaf's class in double, as trace() and inside()
 * use it) agrees with the reference's at random points.
 *
 *   test_csg [RAYS] */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cast.h"
#include "csg.h"
#include "device.h"
#include "diag.h"
#include "eval.h"
#include "lower.h"
#include "parse.h"

static double range(double lo, double hi)
{
	return lo + (hi - lo) * cast_uniform();
}

/* ---- the tree and its reference ---- */

enum { SPHERE, BOX, MESH_BOX, OPEN_MESH, SHEET, CYLINDER, UNION, MERGE, INTERSECTION, DIFFERENCE };
static const char *const names[] = { "sphere", "box", "mesh box", "open mesh", "parametric square", "cylinder",
                                     "union", "merge", "intersection", "difference" };
static int leaf_kinds = 2;   /* leaf() draws the first of these kinds */

#define MAX_KIDS 16
#define MAX_HITS 256

struct node {
	int kind;
	bool inverse;
	double c[3], r;           /* sphere */
	double lo[3], hi[3];      /* box, the meshes; a parametric square at z = c[2] */
	double e[3];              /* cylinder: from c to e, radius r */
	struct node *kid[MAX_KIDS];
	int n_kids;
	struct node *clip;        /* clipped_by { this leaf }, or NULL */
};

struct hits {
	double t[MAX_HITS];
	int n;
};

static double dot3(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* A cylinder's axis (unit) and length, and x's distance along it and from it. */
static void cylinder_frame(const struct node *n, const double x[3], double u[3], double *len, double *s, double *rho)
{
	double v[3] = { n->e[0] - n->c[0], n->e[1] - n->c[1], n->e[2] - n->c[2] };
	*len = sqrt(dot3(v, v));
	for (int k = 0; k < 3; k++)
		u[k] = v[k] / *len;
	double w[3] = { x[0] - n->c[0], x[1] - n->c[1], x[2] - n->c[2] };
	*s = dot3(w, u);
	double r2 = dot3(w, w) - *s * *s;
	*rho = sqrt(r2 > 0 ? r2 : 0);
}

/* How far x is from the leaf's surface, roughly: for the margins. */
static double surface_distance(const struct node *n, const double x[3])
{
	if (n->kind == SHEET) {
		double dx = fmax(0, fmax(n->lo[0] - x[0], x[0] - n->hi[0]));
		double dy = fmax(0, fmax(n->lo[1] - x[1], x[1] - n->hi[1])), dz = x[2] - n->c[2];
		return sqrt(dx * dx + dy * dy + dz * dz);
	}
	if (n->kind == SPHERE) {
		double v[3] = { x[0] - n->c[0], x[1] - n->c[1], x[2] - n->c[2] };
		return fabs(sqrt(dot3(v, v)) - n->r);
	}
	if (n->kind == CYLINDER) {
		double u[3], len, s, rho;
		cylinder_frame(n, x, u, &len, &s, &rho);
		double ds = fmax(0, fmax(-s, s - len)), dr = fmax(0, rho - n->r);
		if (ds == 0 && dr == 0)
			return fmin(n->r - rho, fmin(s, len - s));
		return sqrt(ds * ds + dr * dr);
	}
	if (n->kind == BOX || n->kind == MESH_BOX || n->kind == OPEN_MESH) {
		double inside = INFINITY, out = 0;
		for (int k = 0; k < 3; k++) {
			double a = x[k] - n->lo[k], b = n->hi[k] - x[k];
			inside = fmin(inside, fmin(fabs(a), fabs(b)));
			out = fmax(out, fmax(-a, -b));
		}
		return out > 0 ? out : inside;
	}
	double d = n->clip ? surface_distance(n->clip, x) : INFINITY;
	for (int i = 0; i < n->n_kids; i++)
		d = fmin(d, surface_distance(n->kid[i], x));
	return d;
}

static bool inside(const struct node *n, const double x[3])
{
	bool in;
	if (n->kind == SPHERE) {
		double v[3] = { x[0] - n->c[0], x[1] - n->c[1], x[2] - n->c[2] };
		in = dot3(v, v) < n->r * n->r;
	} else if (n->kind == CYLINDER) {
		double u[3], len, s, rho;
		cylinder_frame(n, x, u, &len, &s, &rho);
		in = s > 0 && s < len && rho < n->r;
	} else if (n->kind == OPEN_MESH || n->kind == SHEET) {
		in = false;
	} else if (n->kind == BOX || n->kind == MESH_BOX) {
		in = true;
		for (int k = 0; k < 3; k++)
			in = in && x[k] > n->lo[k] && x[k] < n->hi[k];
	} else if (n->kind == INTERSECTION || n->kind == DIFFERENCE) {
		in = true;
		for (int i = 0; i < n->n_kids; i++)
			in = in && (inside(n->kid[i], x) != (n->kind == DIFFERENCE && i > 0));
	} else {
		in = false;
		for (int i = 0; i < n->n_kids; i++)
			in = in || inside(n->kid[i], x);
	}
	in = in && (!n->clip || inside(n->clip, x));   /* a clipped object is only inside its clip */
	return in != n->inverse;
}

static void add(struct hits *h, double t)
{
	if (h->n < MAX_HITS)
		h->t[h->n++] = t;
}

/* Every surface point of n along the ray, by POV-Ray's rules. */
static void all_hits(const struct node *n, const double o[3], const double d[3], struct hits *out)
{
	if (n->kind == SPHERE) {
		double oc[3] = { o[0] - n->c[0], o[1] - n->c[1], o[2] - n->c[2] };
		double b = dot3(oc, d), c = dot3(oc, oc) - n->r * n->r, disc = b * b - c;
		if (disc >= 0) {
			add(out, -b - sqrt(disc));
			add(out, -b + sqrt(disc));
		}
		return;
	}
	if (n->kind == SHEET) {
		double t = (n->c[2] - o[2]) / d[2], x = o[0] + t * d[0], y = o[1] + t * d[1];
		if (t > 0 && x >= n->lo[0] && x <= n->hi[0] && y >= n->lo[1] && y <= n->hi[1])
			add(out, t);
		return;
	}
	if (n->kind == CYLINDER) {   /* its side between the caps, and the caps within the radius */
		double u[3], len, s0, rho;
		cylinder_frame(n, o, u, &len, &s0, &rho);
		double w[3] = { o[0] - n->c[0], o[1] - n->c[1], o[2] - n->c[2] }, du = dot3(d, u);
		double pd[3], pw[3];
		for (int k = 0; k < 3; k++) {
			pd[k] = d[k] - du * u[k];
			pw[k] = w[k] - s0 * u[k];
		}
		double a = dot3(pd, pd), b = dot3(pd, pw), c = dot3(pw, pw) - n->r * n->r, disc = b * b - a * c;
		if (a > 0 && disc >= 0)
			for (int sign = -1; sign <= 1; sign += 2) {
				double t = (-b + sign * sqrt(disc)) / a, s = s0 + t * du;
				if (s >= 0 && s <= len)
					add(out, t);
			}
		for (int cap = 0; cap < 2 && du != 0; cap++) {
			double t = ((cap ? len : 0) - s0) / du, x[3];
			for (int k = 0; k < 3; k++)
				x[k] = pw[k] + t * pd[k];
			if (dot3(x, x) <= n->r * n->r)
				add(out, t);
		}
		return;
	}
	if (n->kind == BOX || n->kind == MESH_BOX || n->kind == OPEN_MESH) {
		double t0 = -INFINITY, t1 = INFINITY;
		for (int k = 0; k < 3; k++) {
			double a = (n->lo[k] - o[k]) / d[k], b = (n->hi[k] - o[k]) / d[k];
			t0 = fmax(t0, fmin(a, b));
			t1 = fmin(t1, fmax(a, b));
		}
		if (t0 <= t1) {   /* rays start outside every leaf */
			add(out, t0);
			if (n->kind != OPEN_MESH)
				add(out, t1);
		}
		return;
	}
	for (int i = 0; i < n->n_kids; i++) {
		struct hits h = { .n = 0 };
		all_hits(n->kid[i], o, d, &h);
		for (int j = 0; j < h.n; j++) {
			double x[3] = { o[0] + h.t[j] * d[0], o[1] + h.t[j] * d[1], o[2] + h.t[j] * d[2] };
			bool keep = !n->clip || inside(n->clip, x);
			for (int k = 0; k < n->n_kids && keep; k++) {
				if (k == i)
					continue;
				bool in = inside(n->kid[k], x);
				if (n->kind == MERGE)
					keep = !in;
				else if (n->kind == INTERSECTION)
					keep = in;
				else if (n->kind == DIFFERENCE)
					keep = k == 0 ? in : !in;
			}
			if (keep)
				add(out, h.t[j]);
		}
	}
}

/* Whether the ray passes within a hair of a leaf's silhouette (a box's edge, a
 * sphere's rim), hit or not: where single precision may see a hit the
 * reference does not, or miss one it sees. */
static bool grazes(const struct node *n, const double o[3], const double d[3])
{
	if (n->kind == SPHERE) {
		double oc[3] = { o[0] - n->c[0], o[1] - n->c[1], o[2] - n->c[2] };
		double b = dot3(oc, d), disc = b * b - (dot3(oc, oc) - n->r * n->r);
		return fabs(disc) < 1e-5;
	}
	if (n->kind == BOX || n->kind == MESH_BOX || n->kind == OPEN_MESH) {
		double t0 = -INFINITY, t1 = INFINITY;
		for (int k = 0; k < 3; k++) {
			double a = (n->lo[k] - o[k]) / d[k], b = (n->hi[k] - o[k]) / d[k];
			t0 = fmax(t0, fmin(a, b));
			t1 = fmin(t1, fmax(a, b));
		}
		return fabs(t1 - t0) < 1e-4;
	}
	if (n->kind == CYLINDER) {   /* tangent to its side, or through a rim */
		double u[3], len, s0, rho;
		cylinder_frame(n, o, u, &len, &s0, &rho);
		double w[3] = { o[0] - n->c[0], o[1] - n->c[1], o[2] - n->c[2] }, du = dot3(d, u), pd[3], pw[3];
		for (int k = 0; k < 3; k++) {
			pd[k] = d[k] - du * u[k];
			pw[k] = w[k] - s0 * u[k];
		}
		double a = dot3(pd, pd), b = dot3(pd, pw), c = dot3(pw, pw) - n->r * n->r, disc = b * b - a * c;
		if (fabs(disc) < 1e-5)
			return true;
		for (int cap = 0; cap < 2 && du != 0; cap++) {
			double t = ((cap ? len : 0) - s0) / du, x[3];
			for (int k = 0; k < 3; k++)
				x[k] = pw[k] + t * pd[k];
			if (fabs(sqrt(dot3(x, x)) - n->r) < 1e-4)
				return true;
		}
		return false;
	}
	for (int i = 0; i < n->n_kids; i++)
		if (grazes(n->kid[i], o, d))
			return true;
	return false;
}

/* ---- making trees and their text ---- */

static struct node *leaf(void)
{
	struct node *n = calloc(1, sizeof *n);
	n->kind = (int)(cast_uniform() * leaf_kinds);
	for (int k = 0; k < 3; k++)
		n->c[k] = range(-0.6, 0.6);
	n->r = range(0.4, 0.9);
	for (int k = 0; k < 3; k++) {
		double h = range(0.3, 0.8);
		n->lo[k] = n->c[k] - h;
		n->hi[k] = n->c[k] + h;
	}
	n->c[2] = n->kind == SHEET ? range(-0.5, 0.5) : n->c[2];
	n->inverse = cast_uniform() < 0.1;
	return n;
}

static struct node *tree(int kind, int depth)
{
	struct node *n = calloc(1, sizeof *n);
	n->kind = kind;
	n->n_kids = cast_uniform() < 0.5 ? 2 : 3;
	for (int i = 0; i < n->n_kids; i++)
		n->kid[i] = depth > 1 && cast_uniform() < 0.6 ? tree(UNION + (int)(cast_uniform() * 4), depth - 1) : leaf();
	n->inverse = depth < 3 && cast_uniform() < 0.15;
	return n;
}

static void free_tree(struct node *n)
{
	for (int i = 0; i < n->n_kids; i++)
		free_tree(n->kid[i]);
	if (n->clip)
		free_tree(n->clip);
	free(n);
}

/* A sphere, box or cylinder about centre, of the size scale. */
static struct node *small_leaf(const double centre[3], double scale)
{
	struct node *n = calloc(1, sizeof *n);
	n->kind = (int[]){ SPHERE, BOX, CYLINDER }[(int)(cast_uniform() * 3)];
	for (int k = 0; k < 3; k++)
		n->c[k] = centre[k] + scale * range(-0.2, 0.2);
	n->r = scale * range(0.3, 0.6);
	for (int k = 0; k < 3; k++) {
		double h = scale * range(0.25, 0.5);
		n->lo[k] = n->c[k] - h;
		n->hi[k] = n->c[k] + h;
		n->e[k] = n->c[k] + scale * range(-0.8, 0.8);   /* a cylinder's other end */
	}
	return n;
}

/* A CSG of many leaves about centre, depth levels deep: each part a leaf or
 * a CSG of two to four parts of half the size about a point near it (an
 * intersection's parts closer together, so that they overlap); some parts
 * clipped_by a sphere about them, and some of an intersection's inverse (an
 * inverse part elsewhere would leave little to see). */
static struct node *many_tree(int kind, const double centre[3], double scale, int n_kids, int depth, int parent)
{
	struct node *n = calloc(1, sizeof *n);
	n->kind = kind;
	n->n_kids = n_kids;
	double spread = kind == INTERSECTION ? 0.1 : depth == 3 ? 0.5 : 0.25;
	for (int i = 0; i < n_kids; i++) {
		double c[3];
		for (int k = 0; k < 3; k++)
			c[k] = centre[k] + scale * range(-spread, spread);
		n->kid[i] = depth > 1 && cast_uniform() < 0.7
		          ? many_tree(UNION + (int)(cast_uniform() * 4), c, scale * 0.5, 2 + (int)(cast_uniform() * 3), depth - 1,
		                      kind)
		          : small_leaf(c, scale * 0.5);
	}
	if (depth < 3 && cast_uniform() < 0.25) {
		n->clip = small_leaf(centre, scale);
		n->clip->kind = SPHERE;
		n->clip->r = scale * range(0.3, 0.6);
	} else {
		n->inverse = parent == INTERSECTION && cast_uniform() < 0.3;
	}
	return n;
}

static int count_leaves(const struct node *n)
{
	int c = n->n_kids ? 0 : 1;
	for (int i = 0; i < n->n_kids; i++)
		c += count_leaves(n->kid[i]);
	return c + (n->clip != NULL);
}

/* A box of 12 triangles, with the inside_vector or without. */
static void write_mesh_box(FILE *f, const struct node *n)
{
	fputs("mesh2 { vertex_vectors { 8", f);
	for (int v = 0; v < 8; v++)
		fprintf(f, ", <%.17g, %.17g, %.17g>", v & 1 ? n->hi[0] : n->lo[0], v & 2 ? n->hi[1] : n->lo[1],
		        v & 4 ? n->hi[2] : n->lo[2]);
	fputs(" }\n face_indices { 12, <0, 1, 3>, <0, 3, 2>, <4, 7, 5>, <4, 6, 7>, <0, 4, 5>, <0, 5, 1>, <2, 3, 7>, "
	      "<2, 7, 6>, <0, 2, 6>, <0, 6, 4>, <1, 5, 7>, <1, 7, 3> }\n", f);
	if (n->kind == MESH_BOX)
		fputs(" inside_vector <0.31, 0.52, 0.79>\n", f);
}

static void write_node(FILE *f, const struct node *n)
{
	if (n->kind == MESH_BOX || n->kind == OPEN_MESH)
		write_mesh_box(f, n);
	else if (n->kind == SHEET)
		fprintf(f, "parametric { function { %.17g + u * %.17g } function { %.17g + v * %.17g } function { %.17g }\n"
		        " <0, 0>, <1, 1> contained_by { box { <-3, -3, -3>, <3, 3, 3> } }\n",
		        n->lo[0], n->hi[0] - n->lo[0], n->lo[1], n->hi[1] - n->lo[1], n->c[2]);
	else if (n->kind == SPHERE)
		fprintf(f, "sphere { <%.17g, %.17g, %.17g>, %.17g", n->c[0], n->c[1], n->c[2], n->r);
	else if (n->kind == BOX)
		fprintf(f, "box { <%.17g, %.17g, %.17g>, <%.17g, %.17g, %.17g>", n->lo[0], n->lo[1], n->lo[2], n->hi[0],
		        n->hi[1], n->hi[2]);
	else if (n->kind == CYLINDER)
		fprintf(f, "cylinder { <%.17g, %.17g, %.17g>, <%.17g, %.17g, %.17g>, %.17g", n->c[0], n->c[1], n->c[2],
		        n->e[0], n->e[1], n->e[2], n->r);
	else
		fprintf(f, "%s {\n", names[n->kind]);
	for (int i = 0; i < n->n_kids; i++) {
		write_node(f, n->kid[i]);
		fputc('\n', f);
	}
	if (n->clip) {
		fputs("clipped_by { ", f);
		write_node(f, n->clip);
		fputs(" }", f);
	}
	fprintf(f, "%s }", n->inverse ? " inverse" : "");
}

/* ---- the host ---- */

static int failures;

struct host_leaves {
	const scene *s;
	const scene_object *leaf;
	const double *x;
};

/* A leaf's own inside test on the host, as trace() and inside() make it. */
static bool host_leaf_inside(void *ctx, int k)
{
	const struct host_leaves *c = ctx;
	const scene_object *o = &c->leaf[k];
	xform inv;
	double p[3];
	if (!shape_of(o)->inside || lower_invert(&o->xf, &inv))
		return false;
	scene_xform_point(&inv, c->x, p);
	return shape_of(o)->inside(c->s, o, p);
}

/* The host's inside of the CSG object (its program over its leaves' classes'
 * inside tests, in double) against the reference's at random points, when
 * the tree is one CSG object (a union at the top is only a group); *checked
 * gets how many points were compared. */
static int host_inside_disagrees(const scene *s, const struct node *root, int n_points, int *checked)
{
	*checked = 0;
	if (s->n_csgs != 1 || s->csgs[0].first != 0 || s->csgs[0].n_leaves != s->n_objects)
		return 0;
	int bad = 0;
	for (int i = 0; i < n_points; i++) {
		double x[3] = { range(-1.6, 1.6), range(-1.6, 1.6), range(-1.6, 1.6) };
		if (surface_distance(root, x) < 1e-6)
			continue;
		struct host_leaves c = { s, s->objects, x };
		bool host = csg_inside(s->csgs[0].ops, s->csgs[0].n_ops, host_leaf_inside, &c);
		(*checked)++;
		if (host != inside(root, x) && bad++ < 3)
			printf("  point <%g, %g, %g>: host inside %d, reference %d\n", x[0], x[1], x[2], host, !host);
	}
	return bad;
}

/* ---- the device ---- */

/* One case: the tree as a scene, its rays on the device and in the reference. */
static void run_case(device_ctx *dev, cl_program prog, const char *what, struct node *root, int n_rays)
{
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	fputs("#version 3.7;\n", f);
	write_node(f, root);
	fputc('\n', f);
	fclose(f);
	scene s;
	scene_init(&s);
	ast_node *ast = parse_text(what, text, len);   /* the source table owns text now */
	lower_result lr;
	int ok = ast && eval_scene(ast, &s, NULL) == 0 && diag_error_count() == 0 && lower_scene(&s, NULL, &lr) == 0;
	if (!ok) {
		printf("FAIL: %s: the scene did not evaluate and lower:\n%s\n", what, text);
		failures++;
		ast_free(ast);
		scene_free(&s);
		return;
	}
	float *rays = malloc((size_t)n_rays * 8 * sizeof *rays), *hits = malloc((size_t)n_rays * 4 * sizeof *hits);
	for (int i = 0; i < n_rays; i++) {   /* from a sphere of radius 4 through a point near the middle */
		double u = range(-1, 1), phi = range(0, 2 * M_PI), s2 = sqrt(1 - u * u);
		double o[3] = { 4 * s2 * cos(phi), 4 * s2 * sin(phi), 4 * u }, at[3], d[3];
		for (int k = 0; k < 3; k++)
			at[k] = range(-1.2, 1.2);
		double l = 0;
		for (int k = 0; k < 3; k++) {
			d[k] = at[k] - o[k];
			l += d[k] * d[k];
		}
		for (int k = 0; k < 3; k++) {
			rays[8 * i + k] = (float)o[k];
			rays[8 * i + 4 + k] = (float)(d[k] / sqrt(l));
		}
		rays[8 * i + 3] = INFINITY;
		rays[8 * i + 7] = 0;
	}
	int bad = 0, skipped = 0, hit = 0;
	if (cast_rays(dev, prog, "raycast", &lr, rays, n_rays, hits, 1, -1))
		bad = n_rays;
	for (int i = 0; i < n_rays && bad < n_rays; i++) {
		double o[3], d[3];
		for (int k = 0; k < 3; k++) {   /* the ray the device saw, in double */
			o[k] = rays[8 * i + k];
			d[k] = rays[8 * i + 4 + k];
		}
		struct hits h = { .n = 0 };
		all_hits(root, o, d, &h);
		double best = INFINITY;
		for (int j = 0; j < h.n; j++)
			if (h.t[j] > 1e-6 && h.t[j] < best)
				best = h.t[j];
		/* near another surface, or grazing: single precision may go either way */
		bool close = false;
		for (int j = 0; j < h.n && !close; j++) {
			double x[3] = { o[0] + h.t[j] * d[0], o[1] + h.t[j] * d[1], o[2] + h.t[j] * d[2] };
			close = h.t[j] > 1e-6 && h.t[j] <= best + 1e-3 && surface_distance(root, x) < 1e-9 &&
			        fabs(h.t[j] - best) < 2e-3 && h.t[j] != best;
		}
		for (int j = 0; j < h.n && !close; j++)
			for (int k = j + 1; k < h.n && !close; k++)
				close = fabs(h.t[j] - h.t[k]) < 2e-3 && fmin(h.t[j], h.t[k]) <= best + 2e-3;
		close = close || grazes(root, o, d);
		float t = hits[4 * i];
		bool agree = best == INFINITY ? t == INFINITY : fabs(t - best) < 1e-3;
		if (close) {
			skipped++;
			continue;
		}
		hit += best != INFINITY;
		if (!agree && bad++ < 3)
			printf("  ray %d: device t %.6g, reference %.6g\n", i, t, best);
	}
	int checked, host_bad = host_inside_disagrees(&s, root, n_rays / 4, &checked);
	printf("%s: %s: %d rays, %d hit, %d near another surface left out, %d disagree; host inside: %d points, %d "
	       "disagree\n", bad || host_bad ? "FAIL" : "ok", what, n_rays, hit, skipped, bad, checked, host_bad);
	bad += host_bad;
	if (bad)
		printf("%s\n", text);
	failures += bad > 0;
	free(rays);
	free(hits);
	ast_free(ast);
	lower_free(&lr);
	scene_free(&s);
}

int main(int argc, char **argv)
{
	int n_rays = argc > 1 ? atoi(argv[1]) : 20000;
	cast_seed(0x853c49e6748fea9bull);
	device_ctx dev;
	if (device_open(&dev, -1))
		return 1;
	lower_result probe = { .layout = LOWER_LAYOUT_DEFAULT };
	cl_program prog = device_build(&dev, getenv("ECLAT_KERNEL_DIR"), lower_kernel_options(&probe), NULL);
	if (!prog)
		return 1;
	for (int kind = UNION; kind <= DIFFERENCE; kind++) {   /* each operation alone */
		struct node *t = tree(kind, 1);
		t->inverse = false;
		run_case(&dev, prog, names[kind], t, n_rays);
		free_tree(t);
	}
	struct node *inv = tree(INTERSECTION, 1);   /* an inverse part */
	inv->kid[1]->inverse = true;
	run_case(&dev, prog, "intersection with an inverse part", inv, n_rays);
	free_tree(inv);
	for (int i = 0; i < 24; i++) {   /* three levels deep */
		char what[64];
		struct node *t = tree(UNION + i % 4, 3);
		snprintf(what, sizeof what, "tree %d (%s, three deep)", i, names[UNION + i % 4]);
		run_case(&dev, prog, what, t, n_rays / 4);
		free_tree(t);
	}
	for (int mesh = MESH_BOX; mesh <= SHEET; mesh++)   /* each operation with a mesh first and second */
		for (int kind = UNION; kind <= DIFFERENCE; kind++)
			for (int second = 0; second < 2; second++) {
				char what[96];
				struct node *t = tree(kind, 1);
				t->inverse = false;
				t->kid[second]->kind = mesh;
				t->kid[second]->inverse = false;
				if (mesh == SHEET)
					t->kid[second]->c[2] = range(-0.5, 0.5);
				snprintf(what, sizeof what, "%s with a %s %s", names[kind], names[mesh], second ? "second" : "first");
				run_case(&dev, prog, what, t, n_rays / 4);
				free_tree(t);
			}
	leaf_kinds = SHEET + 1;
	for (int i = 0; i < 16; i++) {   /* meshes anywhere, three levels deep */
		char what[64];
		struct node *t = tree(UNION + i % 4, 3);
		snprintf(what, sizeof what, "tree %d with meshes (%s, three deep)", i, names[UNION + i % 4]);
		run_case(&dev, prog, what, t, n_rays / 4);
		free_tree(t);
	}
	for (int i = 0; i < 8; i++) {   /* many leaves, so that the leaf tree and the program's skips matter */
		char what[96];
		double centre[3] = { 0, 0, 0 };
		struct node *t;
		do {
			t = many_tree(i % 2 ? DIFFERENCE : UNION + i / 2 % 4, centre, 2.0, MAX_KIDS, 3, -1);
			if (i % 2)
				t->kid[0] = (free_tree(t->kid[0]), small_leaf(centre, 5.0));   /* a large first part, drilled */
			if (t->kind == INTERSECTION) {   /* of many parts would be empty: of a union and a merge of them */
				t->n_kids = 2;
				for (int k = 0; k < MAX_KIDS; k++)
					if (k < 2)
						t->kid[k] = (free_tree(t->kid[k]), many_tree(UNION + k, centre, 2.0, MAX_KIDS / 2, 3, -1));
					else
						free_tree(t->kid[k]);
			}
		} while (count_leaves(t) < 40 && (free_tree(t), 1));
		snprintf(what, sizeof what, "many %d (%s, %d leaves, three deep)", i, names[t->kind], count_leaves(t));
		run_case(&dev, prog, what, t, n_rays / 2);
		free_tree(t);
	}
	clReleaseProgram(prog);
	device_close(&dev);
	printf("%s\n", failures ? "FAIL" : "all CSG checks passed");
	return failures ? 1 : 0;
}
