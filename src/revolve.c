/* revolve.c: sor and lathe on the host (src/revolve.h): their profiles from
 * the points as POV-Ray computes them (sor.cpp's Compute_Sor, lathe.cpp's
 * Compute_Lathe), trace() and the inside tests in double precision, and the
 * lowering into one PRIM_SOR (kernels/shape_sor.cl). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lower.h"
#include "revolve.h"

#define POV_EPSILON 1e-10
#define POV_DEPTH_TOLERANCE 1e-4
#define FLAT_MAX 64

static void *xrealloc(void *p, size_t n)
{
	void *q = realloc(p, n ? n : 1);
	if (!q) {
		fputs("eclat: out of memory\n", stderr);
		diag_exit(1);
	}
	return q;
}

static revolve_piece *add_piece(revolve_profile *pr, int *cap)
{
	if (pr->n == *cap) {
		*cap = *cap ? 2 * *cap : 16;
		pr->piece = xrealloc(pr->piece, *cap * sizeof *pr->piece);
	}
	revolve_piece *p = &pr->piece[pr->n++];
	memset(p, 0, sizeof *p);
	p->side = 1;
	return p;
}

static double cubic_at(const double c[4], double h)
{
	return ((c[0] * h + c[1]) * h + c[2]) * h + c[3];
}

/* A curve's squared radius at height h. */
static double piece_at(const revolve_piece *p, double h)
{
	return cubic_at(p->c, h - p->hc);
}

const char *revolve_sor_points(const double (*P)[2], int n)
{
	if (n < 4)
		return "a sor needs at least four points";
	for (int i = 0; i < n; i++)
		if (P[i][0] < 0 || (i > 1 && i < n - 1 && P[i][1] <= P[i - 1][1]))
			return "incorrect point in surface of revolution (a radius below 0, or heights not increasing)";
	for (int i = 0; i + 3 < n; i++)
		if (fabs(P[i + 2][1] - P[i][1]) < POV_EPSILON || fabs(P[i + 3][1] - P[i + 1][1]) < POV_EPSILON)
			return "incorrect point in surface of revolution (a radius below 0, or heights not increasing)";
	return NULL;
}

const char *revolve_lathe_points(int kind, const double (*P)[2], int n)
{
	static const char *const few[] = {
		"a lathe with linear_spline needs at least two points",
		"a lathe with quadratic_spline needs at least three points",
		"a lathe with cubic_spline needs at least four points",
		"a lathe with bezier_spline needs four points per segment",
	};
	static const int least[] = { 2, 3, 4, 4 };
	if (n < least[kind] || (kind == REVOLVE_BEZIER && n % 4 != 0))
		return few[kind];
	for (int i = 0; i < n; i++) {
		bool end = i == 0 || i == n - 1;
		bool checked = kind == REVOLVE_LINEAR ? !end                       /* 3.7 warns at the ends */
		             : kind == REVOLVE_QUADRATIC ? i > 0 && i < n - 1
		             : kind == REVOLVE_CUBIC ? i > 0 && i < n - 1
		             : (i % 4 == 0 || i % 4 == 3) && !end;
		if (checked && P[i][0] < 0)
			return "a lathe's point has a radius (x) below 0";
	}
	return NULL;
}

/* Solves the 4x4 system m x = k by elimination with pivoting; -1 when singular. */
static int solve4(double m[4][4], double k[4], double x[4])
{
	for (int c = 0; c < 4; c++) {
		int piv = c;
		for (int r = c + 1; r < 4; r++)
			if (fabs(m[r][c]) > fabs(m[piv][c]))
				piv = r;
		if (m[piv][c] == 0)
			return -1;
		for (int j = 0; j < 4; j++) {
			double t = m[c][j];
			m[c][j] = m[piv][j];
			m[piv][j] = t;
		}
		double t = k[c];
		k[c] = k[piv];
		k[piv] = t;
		for (int r = c + 1; r < 4; r++) {
			double f = m[r][c] / m[c][c];
			for (int j = c; j < 4; j++)
				m[r][j] -= f * m[c][j];
			k[r] -= f * k[c];
		}
	}
	for (int r = 3; r >= 0; r--) {
		double s = k[r];
		for (int j = r + 1; j < 4; j++)
			s -= m[r][j] * x[j];
		x[r] = s / m[r][r];
	}
	return 0;
}

static void sor_profile(const double (*P)[2], int n, bool open, revolve_profile *pr)
{
	int cap = 0;
	for (int i = 0; i + 3 < n; i++) {
		double k[4] = { P[i + 1][0] * P[i + 1][0], P[i + 2][0] * P[i + 2][0],
		                2 * P[i + 1][0] * (P[i + 2][0] - P[i][0]) / (P[i + 2][1] - P[i][1]),
		                2 * P[i + 2][0] * (P[i + 3][0] - P[i + 1][0]) / (P[i + 3][1] - P[i + 1][1]) };
		double w1 = P[i + 1][1], w2 = P[i + 2][1];
		double m[4][4] = { { w1 * w1 * w1, w1 * w1, w1, 1 }, { w2 * w2 * w2, w2 * w2, w2, 1 },
		                   { 3 * w1 * w1, 2 * w1, 1, 0 }, { 3 * w2 * w2, 2 * w2, 1, 0 } };
		revolve_piece *p = add_piece(pr, &cap);
		p->kind = REVOLVE_CURVE;
		p->h1 = w1;
		p->h2 = w2;
		if (solve4(m, k, p->c))
			memset(p->c, 0, sizeof p->c);
		for (int j = 0; j < 4; j++)
			if (fabs(p->c[j]) < POV_EPSILON)
				p->c[j] = 0;
	}
	int segs = pr->n;
	pr->hmin = P[1][1];
	pr->hmax = P[n - 2][1];
	pr->rmax = 0;
	for (int i = 0; i < segs; i++) {   /* the largest radius: the ends and where f' = 0 */
		const revolve_piece *p = &pr->piece[i];
		double f1 = cubic_at(p->c, p->h1), f2 = cubic_at(p->c, p->h2), a = 3 * p->c[0], b = 2 * p->c[1], c = p->c[2];
		double best = fmax(f1, f2);
		double r[2];
		int nr = 0;
		if (a != 0) {
			double disc = b * b - 4 * a * c;
			if (disc >= 0) {
				r[nr++] = (-b + sqrt(disc)) / (2 * a);
				r[nr++] = (-b - sqrt(disc)) / (2 * a);
			}
		} else if (b != 0) {
			r[nr++] = -c / b;
		}
		for (int j = 0; j < nr; j++)
			if (r[j] >= p->h1 && r[j] <= p->h2)
				best = fmax(best, cubic_at(p->c, r[j]));
		pr->rmax = fmax(pr->rmax, sqrt(fmax(best, 0)));
	}
	if (!open) {
		double base = fmax(cubic_at(pr->piece[0].c, pr->hmin), 0);
		double top = fmax(cubic_at(pr->piece[segs - 1].c, pr->hmax), 0);
		if (base > POV_DEPTH_TOLERANCE) {
			revolve_piece *p = add_piece(pr, &cap);
			*p = (revolve_piece){ .kind = REVOLVE_DISC, .h1 = pr->hmin, .c = { 0, base }, .side = -1 };
		}
		if (top > POV_DEPTH_TOLERANCE) {
			revolve_piece *p = add_piece(pr, &cap);
			*p = (revolve_piece){ .kind = REVOLVE_DISC, .h1 = pr->hmax, .c = { 0, top }, .side = 1 };
		}
	}
}

/* A straight segment of a lathe's profile as a piece, from a (where POV-Ray's
 * v is va) to b (vb). */
static void lathe_segment(revolve_profile *pr, int *cap, const double a[2], const double b[2], double va, double vb)
{
	if (a[0] == b[0] && a[1] == b[1])
		return;
	revolve_piece *p = add_piece(pr, cap);
	if (a[1] == b[1]) {
		double r1 = a[0] * a[0], r2 = b[0] * b[0];
		*p = (revolve_piece){ .kind = REVOLVE_DISC, .h1 = a[1], .c = { fmin(r1, r2), fmax(r1, r2) }, .side = 1,
		                      .v = { r1 <= r2 ? va : vb, r1 <= r2 ? vb : va } };
		if (a[0] * b[0] < 0)   /* it crosses the axis */
			p->c[0] = 0;
		return;
	}
	double s = (b[0] - a[0]) / (b[1] - a[1]);
	*p = (revolve_piece){ .kind = REVOLVE_CURVE, .h1 = fmin(a[1], b[1]), .h2 = fmax(a[1], b[1]), .hc = a[1],
	                      .c = { 0, s * s, 2 * s * a[0], a[0] * a[0] }, .side = 1,
	                      .v = { a[1] < b[1] ? va : vb, a[1] < b[1] ? vb : va } };
}

static void lathe_profile(int kind, const double (*P)[2], int n, revolve_profile *pr)
{
	static const double m[4][4][4] = {
		[REVOLVE_LINEAR] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { -1, 1, 0, 0 }, { 1, 0, 0, 0 } },
		[REVOLVE_QUADRATIC] = { { 0, 0, 0, 0 }, { 0.5, -1, 0.5, 0 }, { -0.5, 0, 0.5, 0 }, { 0, 1, 0, 0 } },
		[REVOLVE_CUBIC] = { { -0.5, 1.5, -1.5, 0.5 }, { 1, -2.5, 2, -0.5 }, { -0.5, 0, 0.5, 0 }, { 0, 1, 0, 0 } },
		[REVOLVE_BEZIER] = { { -1, 3, -3, 1 }, { 3, -6, 3, 0 }, { -3, 3, 0, 0 }, { 1, 0, 0, 0 } },
	};
	int used = kind == REVOLVE_LINEAR ? 2 : kind == REVOLVE_QUADRATIC ? 3 : 4;
	int segs = kind == REVOLVE_LINEAR ? n - 1 : kind == REVOLVE_QUADRATIC ? n - 2 : kind == REVOLVE_CUBIC ? n - 3 : n / 4;
	double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
	for (int i = 0; i < n; i++)
		for (int k = 0; k < 2; k++) {
			lo[k] = fmin(lo[k], P[i][k]);
			hi[k] = fmax(hi[k], P[i][k]);
		}
	double tol = REVOLVE_FLAT * fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), 1e-12);
	int cap = 0;
	for (int s = 0; s < segs; s++) {
		int i = kind == REVOLVE_BEZIER ? 4 * s : s;
		double cf[4][2];
		for (int r = 0; r < 4; r++)
			for (int k = 0; k < 2; k++) {
				cf[r][k] = 0;
				for (int j = 0; j < used; j++)
					cf[r][k] += m[kind][r][j] * P[i + j][k];
			}
		double second = 6 * hypot(cf[0][0], cf[0][1]) + 2 * hypot(cf[1][0], cf[1][1]);
		int steps = second > 0 ? (int)ceil(sqrt(second / (8 * tol))) : 1;
		steps = steps < 1 ? 1 : steps > FLAT_MAX ? FLAT_MAX : steps;
		double prev[2] = { cf[3][0], cf[3][1] }, vprev = (double)s / segs;
		for (int j = 1; j <= steps; j++) {
			double t = (double)j / steps, q[2], v = (s + t) / segs;
			for (int k = 0; k < 2; k++)
				q[k] = ((cf[0][k] * t + cf[1][k]) * t + cf[2][k]) * t + cf[3][k];
			lathe_segment(pr, &cap, prev, q, vprev, v);
			memcpy(prev, q, sizeof prev);
			vprev = v;
		}
	}
	pr->lathe = true;
	pr->rmax = 0;
	pr->hmin = INFINITY;
	pr->hmax = -INFINITY;
	for (int i = 0; i < pr->n; i++) {
		revolve_piece *p = &pr->piece[i];
		double h2 = p->kind == REVOLVE_DISC ? p->h1 : p->h2;
		double r = p->kind == REVOLVE_DISC ? p->c[1] : fmax(piece_at(p, p->h1), piece_at(p, p->h2));
		pr->rmax = fmax(pr->rmax, sqrt(fmax(r, 0)));
		pr->hmin = fmin(pr->hmin, p->h1);
		pr->hmax = fmax(pr->hmax, h2);
	}
	/* each piece's side: whether a point just off it along its normal is inside */
	double eps = 1e-6 * fmax(fmax(pr->rmax, pr->hmax - pr->hmin), 1e-9);
	for (int i = 0; i < pr->n; i++) {
		revolve_piece *p = &pr->piece[i];
		double q[3];
		if (p->kind == REVOLVE_DISC) {
			double r = sqrt((p->c[0] + p->c[1]) / 2);
			q[0] = r, q[1] = p->h1 + eps, q[2] = 0;
		} else {
			double h = (p->h1 + p->h2) / 2, r = sqrt(fmax(piece_at(p, h), 0)), u = h - p->hc;
			double nr = r, nh = -(3 * p->c[0] * u * u + 2 * p->c[1] * u + p->c[2]) / 2, l = hypot(nr, nh);
			if (l == 0)
				continue;
			q[0] = r + eps * nr / l, q[1] = h + eps * nh / l, q[2] = 0;
		}
		p->side = revolve_inside(pr, q) ? -1 : 1;
	}
}

const char *revolve_profile_of(const scene *s, const scene_object *o, revolve_profile *pr)
{
	memset(pr, 0, sizeof *pr);
	if (o->outline < 0 || o->outline >= s->n_outlines)
		return "no points";
	const scene_outline *ol = &s->outlines[o->outline];
	int n = ol->n_edges;
	double (*P)[2] = xrealloc(NULL, (n + 1) * sizeof *P);
	for (int i = 0; i < n; i++) {
		P[i][0] = ol->edge[i][0];
		P[i][1] = ol->edge[i][1];
	}
	const char *bad;
	if (o->shape == SHAPE_SOR) {
		bad = revolve_sor_points((const double (*)[2])P, n);
		if (!bad)
			sor_profile((const double (*)[2])P, n, (o->shape_flags & SHAPE_OPEN) != 0, pr);
	} else {
		int kind = (int)o->param[0];
		bad = revolve_lathe_points(kind, (const double (*)[2])P, n);
		if (!bad)
			lathe_profile(kind, (const double (*)[2])P, n, pr);
	}
	free(P);
	return bad;
}

void revolve_free(revolve_profile *pr)
{
	free(pr->piece);
	memset(pr, 0, sizeof *pr);
}

void revolve_bounds(const revolve_profile *pr, const xform *xf, double lo[3], double hi[3])
{
	if (pr->n == 0)
		return;
	double a[3] = { -pr->rmax, pr->hmin, -pr->rmax }, b[3] = { pr->rmax, pr->hmax, pr->rmax };
	shape_grow_xformed_box(xf, a, b, lo, hi);
}

/* The first root in (lo, hi) of ((g0 t + g1) t + g2) t + g3, else NAN: the
 * closed form when it is a quadratic, else bisection between the roots of its
 * derivative, where it is monotonic. */
static double first_root(const double g[4], double lo, double hi)
{
	if (!(lo < hi))
		return NAN;
	if (g[0] == 0) {
		double a = g[1], b = g[2], c = g[3], r[2];
		int n = 0;
		if (a != 0) {
			double disc = b * b - 4 * a * c;
			if (disc < 0)
				return NAN;
			double q = -0.5 * (b + copysign(sqrt(disc), b));
			r[0] = q / a;
			r[1] = q != 0 ? c / q : r[0];
			n = 2;
		} else if (b != 0) {
			r[0] = -c / b;
			n = 1;
		}
		double best = NAN;
		for (int i = 0; i < n; i++)
			if (r[i] > lo && r[i] < hi && !(r[i] >= best))
				best = r[i];
		return best;
	}
	double cut[4] = { lo }, a = 3 * g[0], b = 2 * g[1], c = g[2];
	int nc = 1;
	double disc = b * b - 4 * a * c;
	if (disc > 0) {
		double q = -0.5 * (b + copysign(sqrt(disc), b)), r1 = q / a, r2 = q != 0 ? c / q : r1;
		double x1 = fmin(r1, r2), x2 = fmax(r1, r2);
		if (x1 > lo && x1 < hi)
			cut[nc++] = x1;
		if (x2 > lo && x2 < hi)
			cut[nc++] = x2;
	}
	cut[nc] = hi;
	for (int i = 0; i < nc; i++) {
		double l = cut[i], r = cut[i + 1];
		double fl = ((g[0] * l + g[1]) * l + g[2]) * l + g[3], fr = ((g[0] * r + g[1]) * r + g[2]) * r + g[3];
		if (fl == 0 && l > lo)
			return l;
		if ((fl < 0) == (fr < 0) && fr != 0)
			continue;
		for (int k = 0; k < 200; k++) {
			double m = 0.5 * (l + r);
			if (m <= l || m >= r)
				break;
			double fm = ((g[0] * m + g[1]) * m + g[2]) * m + g[3];
			if ((fm < 0) == (fl < 0) && fm != 0) {
				l = m;
				fl = fm;
			} else {
				r = m;
			}
		}
		double t = 0.5 * (l + r);
		if (t > lo && t < hi)
			return t;
	}
	return NAN;
}

void revolve_trace(const revolve_profile *pr, const double ro[3], const double rd[3], double tmin, shape_hit *h)
{
	double ox = ro[0], oy = ro[1], oz = ro[2], dx = rd[0], dy = rd[1], dz = rd[2];
	/* the bounding cylinder's span of the ray */
	double R = pr->rmax * (1 + 1e-9) + 1e-12, a = dx * dx + dz * dz, m = ox * dx + oz * dz, c = ox * ox + oz * oz - R * R;
	double c0 = -INFINITY, c1 = INFINITY;
	if (a > 0) {
		double disc = m * m - a * c;
		if (disc < 0)
			return;
		c0 = (-m - sqrt(disc)) / a;
		c1 = (-m + sqrt(disc)) / a;
	} else if (c > 0) {
		return;
	}
	double best = h->t;
	int hit = -1;
	for (int i = 0; i < pr->n; i++) {
		const revolve_piece *p = &pr->piece[i];
		if (p->kind == REVOLVE_DISC) {
			if (dy == 0)
				continue;
			double t = (p->h1 - oy) / dy, x = ox + t * dx, z = oz + t * dz, r2 = x * x + z * z;
			if (t > tmin && t < best && r2 >= p->c[0] && r2 <= p->c[1]) {
				best = t;
				hit = i;
			}
			continue;
		}
		double lo = fmax(tmin, c0), hi = fmin(best, c1);
		if (dy != 0) {
			double t1 = (p->h1 - oy) / dy, t2 = (p->h2 - oy) / dy;
			lo = fmax(lo, fmin(t1, t2));
			hi = fmin(hi, fmax(t1, t2));
		} else if (oy < p->h1 || oy > p->h2) {
			continue;
		}
		if (!(lo < hi))
			continue;
		const double *f = p->c;
		double u = oy - p->hc;
		double g[4] = { f[0] * dy * dy * dy, dy * dy * (3 * f[0] * u + f[1]) - a,
		                dy * (u * (3 * f[0] * u + 2 * f[1]) + f[2]) - 2 * m,
		                cubic_at(f, u) - ox * ox - oz * oz };
		double t = first_root(g, lo, hi);
		if (t == t) {
			best = t;
			hit = i;
		}
	}
	if (hit < 0)
		return;
	const revolve_piece *p = &pr->piece[hit];
	h->t = best;
	if (p->kind == REVOLVE_DISC) {
		h->n[0] = h->n[2] = 0;
		h->n[1] = p->side;
		return;
	}
	double y = oy + best * dy - p->hc;
	h->n[0] = p->side * (ox + best * dx);
	h->n[1] = -p->side * (3 * p->c[0] * y * y + 2 * p->c[1] * y + p->c[2]) / 2;
	h->n[2] = p->side * (oz + best * dz);
	if (h->n[0] == 0 && h->n[1] == 0 && h->n[2] == 0)
		h->n[1] = 1;
}

bool revolve_inside(const revolve_profile *pr, const double p[3])
{
	double y = p[1], r2 = p[0] * p[0] + p[2] * p[2];
	if (!(y >= pr->hmin && y <= pr->hmax) || r2 > pr->rmax * pr->rmax)
		return false;
	if (!pr->lathe) {   /* POV-Ray's sor: the first segment at the height */
		for (int i = 0; i < pr->n; i++) {
			const revolve_piece *q = &pr->piece[i];
			if (q->kind == REVOLVE_CURVE && y >= q->h1 && y <= q->h2)
				return r2 <= piece_at(q, y);
		}
		return false;
	}
	bool in = false;   /* a lathe: the profile's crossings beyond the point */
	for (int i = 0; i < pr->n; i++) {
		const revolve_piece *q = &pr->piece[i];
		if (q->kind == REVOLVE_CURVE && y >= q->h1 && y < q->h2 && piece_at(q, y) >= r2)
			in = !in;
	}
	return in;
}

int revolve_lower(struct lowering *lw, const revolve_profile *pr, const scene_object *o, int mat, int id)
{
	if (pr->n == 0)
		return 0;
	dev_prim p = { .type = PRIM_SOR };
	if (lower_local_rows(&o->xf, &p)) {
		diag_warning(o->loc, "%s with a singular transform (a scale of 0?) skipped", shape_of(o)->name);
		return 0;
	}
	union { int i; float f; } n = { .i = pr->n }, lathe = { .i = pr->lathe }, kind;
	/* the side in the kind's bit 1, the height the cubic is about in z (a disc: its side in z) */
	p.link = lower_add_data(lw, (float4){ (float)pr->rmax, (float)pr->hmin, (float)pr->hmax, n.f });
	lower_add_data(lw, (float4){ lathe.f, 0, 0, 0 });
	for (int i = 0; i < pr->n; i++) {
		const revolve_piece *q = &pr->piece[i];
		kind.i = q->kind | (q->side < 0 ? 2 : 0);
		lower_add_data(lw, (float4){ (float)q->c[0], (float)q->c[1], (float)q->c[2], (float)q->c[3] });
		lower_add_data(lw, (float4){ (float)q->h1, (float)q->h2, (float)(q->kind == REVOLVE_DISC ? q->side : q->hc), kind.f });
	}
	for (int i = 0; i < pr->n && pr->lathe; i++)   /* a lathe's v at its pieces' ends (sor_uv) */
		lower_add_data(lw, (float4){ (float)pr->piece[i].v[0], (float)pr->piece[i].v[1], 0, 0 });
	double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
	revolve_bounds(pr, &o->xf, lo, hi);
	lower_add_prim(lw, p, mat, id, lo, hi);
	return 0;
}

/* ---- the class functions of sor and lathe (shape_sor.c, shape_lathe.c) ---- */

void revolve_shape_bounds(const scene *s, const scene_object *o, double lo[3], double hi[3])
{
	revolve_profile pr;
	if (!revolve_profile_of(s, o, &pr))
		revolve_bounds(&pr, &o->xf, lo, hi);
	revolve_free(&pr);
}

void revolve_shape_trace(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
                         shape_hit *h)
{
	revolve_profile pr;
	if (!revolve_profile_of(s, o, &pr))
		revolve_trace(&pr, ro, rd, tmin, h);
	revolve_free(&pr);
}

bool revolve_shape_inside(const scene *s, const scene_object *o, const double p[3])
{
	revolve_profile pr;
	bool in = !revolve_profile_of(s, o, &pr) && revolve_inside(&pr, p);
	revolve_free(&pr);
	return in;
}

int revolve_shape_lower(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id)
{
	revolve_profile pr;
	const char *bad = revolve_profile_of(s, o, &pr);
	int rc = 0;
	if (bad) {
		diag_error(o->loc, "%s", bad);
		rc = -1;
	} else {
		rc = revolve_lower(lw, &pr, o, mat, id);
	}
	revolve_free(&pr);
	return rc;
}
