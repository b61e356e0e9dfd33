/* shape.h: the table of shapes.
 *
 * A shape of the scene language is a row of SCENE_SHAPES (scene.h) and one
 * host file, src/shape_NAME.c, which defines its class shape_NAME: how it is
 * written (its positional arguments), its bounds, POV-Ray's trace() and inside
 * test on the host in double precision, its lowering into device primitives,
 * and its line in --dump-scene. On the device it is a row of PRIM_SHAPES
 * (kernels/shared.h) and one file, kernels/shape_NAME.cl, with its
 * intersection, normal and inside test. A new shape adds those two rows, those
 * two files (listed in Makefile.am), its syntax block in eclat-scene(5) and
 * its tests; the parser, evaluator, lowering and kernels dispatch on the rows.
 *
 * The host side here is what the evaluator (parsing, trace(), min_extent), the
 * scene (bounds, dump) and the lowering share; each stage calls only its own
 * entries. */
#ifndef ECLAT_SHAPE_H
#define ECLAT_SHAPE_H

#include <stdbool.h>
#include <stdio.h>

#include "scene.h"

struct lowering;

/* A hit in the object's own space: the distance along the ray as given (not
 * unit length) and the outward normal there, not unit length. */
typedef struct {
	double t;
	double n[3];
} shape_hit;

#define SHAPE_TRACE_EPSILON 1e-9   /* trace() skips hits nearer the start than this */

typedef struct {
	const char *name;    /* the keyword */
	/* Positional arguments, in order: v a vector, f a float (the first goes to
	 * radius, the others to param[0], param[1]...); after '|', optional.
	 * NULL: arguments of no fixed shape (a count and then that many points,
	 * keywords, strings), which src/eval_outline.c reads for the kind (polygon,
	 * prism, text); a new such shape adds its reader there. */
	const char *args;
	const char *needs;   /* what an error says the shape needs: "a centre and a radius" */
	int flags;           /* SHAPE_OPEN, SHAPE_STURM: the flags it takes */
	/* A message when the arguments make no shape POV-Ray would draw (an error at
	 * the shape's line), or NULL. May be NULL. */
	const char *(*check)(const scene_object *o);
	/* Grows [lo, hi] by the shape's box in world space. */
	void (*bounds)(const scene *s, const scene_object *o, double lo[3], double hi[3]);
	/* The nearest hit with tmin < t < h->t of the ray (o, d) in object space
	 * into h (t and the outward normal); leaves h alone when there is none. */
	void (*trace)(const scene *s, const scene_object *o, const double ro[3], const double rd[3], double tmin,
	              shape_hit *h);
	/* Whether a point in object space is inside (POV-Ray's Inside); NULL: never. */
	bool (*inside)(const scene *s, const scene_object *o, const double p[3]);
	/* Its device primitives (through the lower_ calls below); 0, or -1 after an
	 * error. mat is its material, id its object number. */
	int (*lower)(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id);
	/* Its words in --dump-scene, in world space: "sphere centre <...> radius 1". */
	void (*dump)(FILE *out, const scene_object *o);
} shape_class;

#define SHAPE_CLASS_DECL(NAME, name) extern const shape_class shape_##name;
SCENE_SHAPES(SHAPE_CLASS_DECL)

const shape_class *shape_of(const scene_object *o);
/* The class of a keyword (and its kind into *kind, when kind is not NULL), or NULL. */
const shape_class *shape_named(const char *name, scene_shape *kind);

/* ---- helpers the shape files share (shape.c) ---- */

void shape_grow_box(double lo[3], double hi[3], const double p[3]);
/* The bounds of a shape with none (a plane, a quadric, a poly): +-1e10, as POV-Ray
 * gives them. */
void shape_unbounded(const scene *s, const scene_object *o, double lo[3], double hi[3]);
/* Grows [lo, hi] by the world image of the box [a, b] of object space. */
void shape_grow_xformed_box(const xform *xf, const double a[3], const double b[3], double lo[3], double hi[3]);
/* A unit vector and two more making a right-handed orthonormal frame with it. */
void shape_frame(const double n[3], double u[3], double v[3]);
/* POV-Ray's Compute_Coordinate_Transform: the map from a shape's own space to
 * object space that scales x and y by radius and z by length, turns z onto the
 * unit vector up (about the axis z x up) and moves the origin to origin. The
 * cylinder, cone and disc are kept in such spaces, so their boxes (and
 * min_extent) are POV-Ray's. */
xform shape_coordinate_xform(const double origin[3], const double up[3], double radius, double length);

/* A placed mesh's inside (shape_mesh.c; the shapes made into meshes too): the
 * direction d in the mesh's space along which an odd number of crossings puts
 * a point inside (POV-Ray's inside_vector, a world direction; a height
 * field's up), and 0; or -1 when it has no inside, and then offers a CSG only
 * its nearest hit along a ray, as POV-Ray's mesh and parametric do. */
int shape_mesh_inside_dir(const scene *s, const scene_object *o, double d[3]);
/* How many times the ray (p, d) in the mesh's space crosses it, each hit the
 * nearest past the one before (hits at one distance count once). */
int shape_mesh_crossings(const scene *s, const scene_object *o, const double p[3], const double d[3]);

/* ---- --dump-scene's words (scene.c) ---- */

void scene_dump_num(FILE *out, double v);
void scene_dump_vec(FILE *out, const char *label, const double v[3]);
/* " matrix <...>" unless t is the identity. */
void scene_dump_xform(FILE *out, const xform *t);

/* ---- lowering (lower.c), for the shapes' lower functions ---- */

/* Adds p (its type and numbers set, its link the PRIM_DATA record it reads,
 * or -1) to the primitives being made, with the material and object; lo and hi are its world box (NULL for a triangle, whose
 * corners give it, and for a plane, which has none). */
void lower_add_prim(struct lowering *lw, dev_prim p, int material, int object, const double lo[3],
                    const double hi[3]);
/* A PRIM_DATA record holding a: the link to it. */
int lower_add_data(struct lowering *lw, float4 a);
/* The same holding three numbers a, b and c. */
int lower_add_record(struct lowering *lw, float4 a, float4 b, float4 c);
/* A triangle (smooth with normals, else NULL), unless it has no area. */
void lower_add_triangle(struct lowering *lw, const double v[3][3], const double (*normals)[3], int material,
                        int object, src_loc loc);
/* Makes material mat (the blob o's own, just added) the blend of its
 * components' textures (lower_texture_blob). */
void lower_blob_textures(struct lowering *lw, const scene_object *o, int mat);
/* Whether the shapes lowered now are a CSG's leaves. */
bool lower_in_csg(const struct lowering *lw);
/* Sets p's rows to the inverse of local-to-world (the shape's own space to the
 * world); -1 when it is singular. */
int lower_local_rows(const xform *local_to_world, dev_prim *p);
/* As lower_local_rows, about a centre: *c is the centre in floats and the rows'
 * w the map's value there, so the kernels take a point x to the shape's space
 * as rows . (x - c) + w (intersect_to_local_about), and far from the origin
 * round only x - c, not x and the map's translation, which cancel. */
int lower_local_rows_about(const xform *local_to_world, const double centre[3], dev_prim *p, float4 *c);
/* A placed mesh (shape_mesh.c's lowering). */
int lower_mesh_instance(struct lowering *lw, const scene *s, const scene_object *o, int mat, int id);

#endif
