/* shape.cl: the dispatch over the table of shapes (PRIM_SHAPES in shared.h),
 * and the surface at a hit, which every integrator reads through
 * texture_point. */

#define SHAPE_INTERSECT_ROW(NAME, name) \
	case PRIM_##NAME: return name##_intersect(o, d, prims, p, tmin, tmax);
#define SHAPE_NORMAL_ROW(NAME, name) \
	case PRIM_##NAME: return name##_normal(prims, p, x);
#define SHAPE_INSIDE_ROW(NAME, name) \
	case PRIM_##NAME: return name##_inside(prims, p, x);
#define SHAPE_INTERSECT_SCENE_ROW(NAME, name) \
	case PRIM_##NAME: return name##_intersect(sc, o, d, prims, p, tmin, tmax);
#define SHAPE_NORMAL_SCENE_ROW(NAME, name) \
	case PRIM_##NAME: return name##_normal(sc, prims, p, x);
#define SHAPE_INSIDE_SCENE_ROW(NAME, name) \
	case PRIM_##NAME: return name##_inside(sc, prims, p, x);

/* sc: the scene's buffers, or 0 where there are none (raycast.cl's test
 * kernels), for the shapes whose functions read them (PRIM_SHAPES' S rows). */
static inline float shape_intersect(const scene_data *sc, float3 o, float3 d, global const dev_prim *prims,
                                    global const dev_prim *p, float tmin, float tmax)
{
	switch (p->type) {
	PRIM_SHAPES(SHAPE_INTERSECT_ROW, SHAPE_INTERSECT_SCENE_ROW)
	default: return tmax;
	}
}

static inline float3 shape_normal(const scene_data *sc, global const dev_prim *prims, global const dev_prim *p,
                                  float3 x)
{
	switch (p->type) {
	PRIM_SHAPES(SHAPE_NORMAL_ROW, SHAPE_NORMAL_SCENE_ROW)
	default: return (float3)(0.0f, 1.0f, 0.0f);
	}
}

static inline bool shape_inside(const scene_data *sc, global const dev_prim *prims, global const dev_prim *p,
                                float3 x)
{
	switch (p->type) {
	PRIM_SHAPES(SHAPE_INSIDE_ROW, SHAPE_INSIDE_SCENE_ROW)
	default: return false;
	}
}

/* The shapes next-event estimation samples (PRIM_EMITTERS in shared.h), each
 * by its own name_emit_sample and name_emit_pdf: a point pos on the shape seen
 * from x along wi, from u1 and u2 (false: none this time); and the density,
 * in solid angle from x, with which that sampler gives the point t along wi,
 * times pick (the probability of having chosen the shape), area the emitter
 * table's. A ray that meets an emitter weighs itself with the same density, so
 * the two must agree exactly. */
#define SHAPE_EMIT_SAMPLE_ROW(NAME, name) \
	case PRIM_##NAME: return name##_emit_sample(prims, p, x, u1, u2, wi, pos);
#define SHAPE_EMIT_PDF_ROW(NAME, name) \
	case PRIM_##NAME: return name##_emit_pdf(prims, p, x, wi, t, pick, area);

static inline bool shape_emit_sample(global const dev_prim *prims, global const dev_prim *p, float3 x, float u1,
                                     float u2, float3 *wi, float3 *pos)
{
	switch (p->type) {
	PRIM_EMITTERS(SHAPE_EMIT_SAMPLE_ROW)
	default: return false;
	}
}

static inline float shape_emit_pdf(global const dev_prim *prims, global const dev_prim *p, float3 x, float3 wi,
                                   float t, float pick, float area)
{
	switch (p->type) {
	PRIM_EMITTERS(SHAPE_EMIT_PDF_ROW)
	default: return 0.0f;
	}
}

/* The emitter table's row of a primitive of the top level, or -1: in its link
 * for the shapes that have no PRIM_DATA record (triangles, spheres), else in
 * the link of its first record. */
static inline int shape_emitter(global const dev_prim *prims, global const dev_prim *p)
{
	switch (p->type) {
	case PRIM_TRIANGLE: case PRIM_SPHERE: return p->link;
	case PRIM_DISC: case PRIM_CYLINDER: return prims[p->link].link;
	default: return -1;
	}
}

/* POV-Ray's uv at a hit x (lx: in the primitive's space, a mesh's for its
 * triangles), for uv_mapping: the shapes that define one (a mesh's triangles,
 * not a lone triangle, and so a bicubic_patch's and a parametric's, whose
 * corners carry their uv); every other shape gives x's own x and y, as
 * POV-Ray's default UVCoord does. */
static inline float2 shape_uv(global const dev_prim *prims, global const float4 *normals, int prim, int inst, float3 lx,
                       float3 x)
{
	global const dev_prim *p = &prims[prim];
	if (inst >= 0 && (p->type == PRIM_TRIANGLE || p->type == PRIM_SMOOTH_TRIANGLE))   /* a mesh's */
		return triangle_uv(p, normals + 3 * p->link, lx);
	switch (p->type) {
	case PRIM_SPHERE: return sphere_uv(prims, p, lx);
	case PRIM_ELLIPSOID: return ellipsoid_uv(prims, p, lx);
	case PRIM_BOX: return box_uv(prims, p, lx);
	case PRIM_TORUS: return torus_uv(prims, p, lx);
	case PRIM_SOR: return sor_uv(prims, p, lx);
	default: return x.xy;
	}
}

/* The surface at a hit: normals in world space (geometric, and shading, which
 * smooth triangles interpolate), and the material and object, which a mesh's
 * triangle may take from its instance. */
typedef struct {
	float3 ng, ns;
	float3 object_x;  /* the hit in its instance's space (a mesh's), else in world space */
	int material, object;
	int emitter;   /* index into the emitter table, or -1 */
} intersect_surface;

/* flip: the hit is on a CSG leaf whose outside is the CSG's inside there (a
 * subtracted shape), so the normal turns over. */
static inline intersect_surface intersect_surface_at(const scene_data *sc, global const dev_prim *prims,
                                                     global const float4 *normals,
                                              int prim, int inst, bool flip, float3 x)
{
	global const dev_prim *p = &prims[prim];
	intersect_surface s = { (float3)(0.0f), (float3)(0.0f), x, p->material, p->object, -1 };
	float3 lx = x;
	if (inst >= 0) {
		global const dev_prim *q = &prims[inst];
		lx = intersect_to_local(q, x);
		if (s.material < 0)
			s.material = q->material;
		s.object = q->object;
	} else {
		s.emitter = shape_emitter(prims, p);
	}
	s.object_x = lx;
	s.ng = shape_normal(sc, prims, p, lx);
	s.ns = s.ng;
	if (p->type == PRIM_SMOOTH_TRIANGLE) {
		float3 ns = triangle_smooth_normal(p, normals + 3 * p->link, lx);
		if (dot(ns, ns) > 0.0f)   /* on the geometric normal's side, as the face's winding says */
			s.ns = dot(ns, s.ng) < 0.0f ? -ns : ns;
	}
	if (p->type == PRIM_TORUS)   /* POV-Ray's, which is not the spindle's geometric one */
		s.ns = torus_shading_normal(p, lx);
	if (inst >= 0) {
		s.ng = intersect_normal_to_world(&prims[inst], s.ng);
		s.ns = intersect_normal_to_world(&prims[inst], s.ns);
	}
	if (flip) {
		s.ng = -s.ng;
		s.ns = -s.ns;
	}
	return s;
}
