/* shape_isosurface.cl: POV-Ray's isosurface, kept as the map from world space
 * to its own, where its function (scene.functions, run by function.cl) is
 * below its threshold inside, within its container (a box or a sphere). Its
 * three PRIM_DATA records (src/shape_isosurface.c):
 *   [0] xyz: the box's low corner, or the sphere's centre; w: the function
 *   [1] xyz: the box's high corner, or x the sphere's radius; w: threshold
 *   [2] x: accuracy, y: max_gradient, z: max_trace, w: ISO_ flags
 *
 * A ray's hits are POV-Ray 3.7's (IsoSurface::All_Intersections), found the
 * same way from the ray's origin so that every caller, a CSG's after another
 * hit among them, sees the same list: the container's surface where the
 * function is inside there (unless open), then up to max_trace roots of the
 * function along the ray within the container, each found by halving the
 * stretch while max_gradient says the function may reach the threshold in
 * it, down to stretches shorter than accuracy (Function_Find_Root). The
 * host's twin is trace() in src/shape_isosurface.c, which refuses a function
 * that calls the scene's patterns: only the device evaluates those, through
 * the scene's buffers that the isosurface's functions take (PRIM_SHAPES' S
 * row). */

enum { ISO_OPEN = 1, ISO_POSITIVE = 2, ISO_SPHERE = 4 };
#define ISO_MAX_TRACE 10
#define ISO_STACK 48

typedef struct {
	real3 lo, hi;          /* box corners; sphere: lo the centre, hi.x the radius */
	int fn, flags, max_trace;
	real threshold, accuracy, max_gradient;
	const scene_data *sc;  /* for its function's pattern calls */
} iso_shape;

static inline iso_shape iso_shape_of(const scene_data *sc, global const dev_prim *prims, global const dev_prim *p)
{
	float4 a = prims[p->link].a, b = prims[p->link + 1].a, c = prims[p->link + 2].a;
	iso_shape s;
	s.lo = convert_real3(a.xyz);
	s.hi = convert_real3(b.xyz);
	s.fn = (int)a.w;
	s.threshold = (real)b.w;
	s.accuracy = (real)c.x;
	s.max_gradient = (real)c.y;
	s.max_trace = (int)c.z;
	s.flags = (int)c.w;
	s.sc = sc;
	return s;
}

/* The function less the threshold, negative inside (POV-Ray's EvaluatePolarized). */
static inline real iso_value(const iso_shape *s, real3 x)
{
	real f = scene_function_at(s->sc, s->fn, x.x, x.y, x.z);
	return (s->flags & ISO_POSITIVE) ? s->threshold - f : f - s->threshold;
}

/* Where the ray enters and leaves the container: false when it misses. */
static inline bool iso_container(const iso_shape *s, real3 P, real3 D, real *t1, real *t2)
{
	if (s->flags & ISO_SPHERE) {
		real3 oc = P - s->lo;
		real a = dot(D, D), b = dot(oc, D), c = dot(oc, oc) - s->hi.x * s->hi.x;
		real disc = b * b - a * c;
		if (!(disc > 0) || a == 0)
			return false;
		real q = sqrt(disc);
		*t1 = (-b - q) / a;
		*t2 = (-b + q) / a;
	} else {
		real3 inv = (real)1 / D;
		real3 ta = (s->lo - P) * inv, tb = (s->hi - P) * inv;
		real3 lo = fmin(ta, tb), hi = fmax(ta, tb);
		*t1 = fmax(lo.x, fmax(lo.y, lo.z));
		*t2 = fmin(hi.x, fmin(hi.y, hi.z));
	}
	return *t2 > *t1 && *t2 > (real)0;
}

/* POV-Ray's Function_Find_Root: the first root after *t1 up to t2, its sign
 * of inside flipped by *inv (which an open isosurface may turn), by halving
 * depth first, nearest half first, without recursion. */
static inline bool iso_find_root(const iso_shape *s, real3 P, real3 D, real t1, real t2, int *inv, real *root)
{
	real vlen = length(D);
	real at = t1, af = (real)*inv * iso_value(s, P + t1 * D);
	if ((s->flags & ISO_OPEN) && af < 0) {
		*inv = -*inv;
		af = -af;
	}
	real bt = t2, bf = (real)*inv * iso_value(s, P + t2 * D);
	real t21 = t2 - t1, dt = s->max_gradient * vlen * t21;
	real stack_t[ISO_STACK], stack_f[ISO_STACK];
	int n = 0;
	for (;;) {
		if (t21 < s->accuracy || n == ISO_STACK) {
			if (bf < 0) {
				*root = bt;
				return true;
			}
		} else if (af + bf - dt < 0) {   /* the threshold may be reached in [at, bt]: halve */
			t21 *= (real)0.5;
			dt *= (real)0.5;
			stack_t[n] = bt;
			stack_f[n] = bf;
			n++;
			bt = at + t21;
			bf = (real)*inv * iso_value(s, P + bt * D);
			continue;
		}
		if (n == 0)   /* the next stretch: the right half of the last one halved */
			return false;
		at = bt;
		af = bf;
		n--;
		bt = stack_t[n];
		bf = stack_f[n];
		t21 = bt - at;
		dt = s->max_gradient * vlen * t21;
	}
}

static inline float isosurface_intersect(const scene_data *sc, float3 o, float3 d, global const dev_prim *prims,
                                         global const dev_prim *p, float tmin, float tmax)
{
	iso_shape s = iso_shape_of(sc, prims, p);
	real3 P = intersect_to_local_real(p, o), D = intersect_dir_to_local_real(p, d);
	real t1, t2;
	if (!iso_container(&s, P, D, &t1, &t2))
		return tmax;
	real acc = s.accuracy, near = (real)4 * s.max_gradient * acc;
	real hits[ISO_MAX_TRACE + 2];
	int n = 0, traced = 0, inv = 1;
	t1 = fmax(t1, (real)0);
	if (!(s.flags & ISO_OPEN)) {   /* the container's surface, where it is inside */
		real v = iso_value(&s, P + t1 * D);
		if (t1 > acc) {
			if (v < 0) {
				hits[n++] = t1;
				traced++;
				inv = -1;
			}
		} else {
			if (v < near) {
				t1 = acc * (real)5;
				if (iso_value(&s, P + t1 * D) < 0)
					inv = -1;
			}
			if (iso_value(&s, P + t2 * D) < 0)
				hits[n++] = t2;
		}
	}
	t1 = fmin(t1, t2);
	if (t2 - t1 < acc)
		return tmax;
	if (t1 < acc && inv == 1 && fabs(iso_value(&s, P + t1 * D)) < near) {   /* starting on the surface */
		t1 = acc * (real)5;
		if (iso_value(&s, P + t1 * D) < 0)
			inv = -1;
	}
	for (; traced < s.max_trace; traced++) {
		real root;
		if (!iso_find_root(&s, P, D, t1, t2, &inv, &root))
			break;
		hits[n++] = root;
		t1 = root + acc * (real)5;
		if (t2 - t1 < acc)
			break;
		inv = -inv;
	}
	float best = tmax;
	for (int i = 0; i < n; i++) {
		float t = (float)hits[i];
		if (t > tmin && t < best)
			best = t;
	}
	return best;
}

/* The container's normal where x is on its surface (and the function inside
 * there), else the function's gradient by POV-Ray's forward differences. */
static inline float3 isosurface_normal(const scene_data *sc, global const dev_prim *prims, global const dev_prim *p,
                                       float3 x)
{
	iso_shape s = iso_shape_of(sc, prims, p);
	real3 v = intersect_to_local_real(p, x), n;
	real size = (s.flags & ISO_SPHERE) ? s.hi.x : fmax(fmax(s.hi.x - s.lo.x, s.hi.y - s.lo.y), s.hi.z - s.lo.z);
	real eps = (real)1e-4 * fmax(size, (real)1), f = iso_value(&s, v);
	bool on_container;
	if (s.flags & ISO_SPHERE) {
		n = v - s.lo;
		on_container = fabs(length(n) - s.hi.x) < eps;
	} else {
		real3 dlo = fabs(v - s.lo), dhi = fabs(v - s.hi);
		real m = fmin(fmin(fmin(dlo.x, dlo.y), dlo.z), fmin(fmin(dhi.x, dhi.y), dhi.z));
		n = (real3)(dlo.x == m ? -1 : dhi.x == m ? 1 : 0, 0, 0);
		if (n.x == 0)
			n = (real3)(0, dlo.y == m ? -1 : dhi.y == m ? 1 : 0, 0);
		if (n.x == 0 && n.y == 0)
			n = (real3)(0, 0, dlo.z == m ? -1 : 1);
		on_container = m < eps;
	}
	if (!(on_container && f < -(real)2 * s.max_gradient * s.accuracy)) {
		real acc = s.accuracy;
		n = (real3)(iso_value(&s, v + (real3)(acc, 0, 0)) - f, iso_value(&s, v + (real3)(0, acc, 0)) - f,
		            iso_value(&s, v + (real3)(0, 0, acc)) - f);
		if (n.x == 0 && n.y == 0 && n.z == 0)
			n.x = 1;
	}
	return intersect_normal_to_world(p, convert_float3(n));
}

static inline bool isosurface_inside(const scene_data *sc, global const dev_prim *prims, global const dev_prim *p,
                                     float3 x)
{
	iso_shape s = iso_shape_of(sc, prims, p);
	real3 v = intersect_to_local_real(p, x);
	bool in_container = (s.flags & ISO_SPHERE) ? length(v - s.lo) <= s.hi.x
	                  : all(v >= s.lo) && all(v <= s.hi);
	return in_container && iso_value(&s, v) < 0;
}
