/* lower.h: the scene flattened into the buffers the kernels read, plus its BVHs:
 * one for the top level (the scene's primitives and one instance per placed
 * mesh) and one per mesh, stored once however often the mesh is placed. */
#ifndef ECLAT_LOWER_H
#define ECLAT_LOWER_H

#include <stddef.h>

#include "../kernels/shared.h"
#include "bvh.h"
#include "csg.h"
#include "scene.h"

enum { LOWER_BVH_SAH, LOWER_BVH_MEDIAN };
/* The node layout the kernels read (--bvh-layout): the builders' binary tree
 * as it is, or converted to 4-wide nodes (bvh_wnode). */
enum { LOWER_LAYOUT_BINARY, LOWER_LAYOUT_WIDE };
#define LOWER_LAYOUT_DEFAULT LOWER_LAYOUT_WIDE

/* The farthest coordinate the kernels can intersect in single precision: its
 * square, summed three times, stays within float's range. Objects past it are
 * left out with a warning. */
#define LOWER_FAR 1e18

typedef struct {
	int builder;        /* LOWER_BVH_SAH (default) or LOWER_BVH_MEDIAN */
	int median_depth;   /* the median builder's maximum depth */
	int layout;         /* LOWER_LAYOUT_BINARY or LOWER_LAYOUT_WIDE */
	int skip_unsupported;  /* --skip-unsupported: what lowering cannot do is left out with a warning */
	int width, height;  /* the image's, for a mesh_camera's rays */
	struct lower_cache *cache;  /* meshes' BVHs kept between calls (an animation's frames), or NULL */
	int kernels;        /* the entry points a render launches (LOWER_KERNELS_); 0: all of them */
} lower_options;

/* Each integrator's kernel inlines the whole of its tracing and shading, and
 * PoCL compiles every kernel of a program: a render builds only those it
 * launches (lower_kernel_options), a build a quarter as long. */
enum { LOWER_KERNELS_PATH = 1, LOWER_KERNELS_WHITTED = 2, LOWER_KERNELS_WHITTED_AA1 = 4,
       LOWER_KERNELS_WHITTED_AA2 = 8 };

/* The BVHs of meshes, kept from one lower_scene to the next (lower_cache.c):
 * a mesh whose triangles are those of a mesh of the previous call gets a copy
 * of its tree instead of a build. */
typedef struct lower_cache lower_cache;
lower_cache *lower_cache_new(void);   /* NULL when out of memory */
void lower_cache_free(lower_cache *c);
int lower_cache_hits(const lower_cache *c);   /* trees copied, not built, so far */
/* ---- between lower.c and lower_cache.c: 1 and a copy in *t when kept; keep
 * stores a copy of the triangles p (before the build) and of their tree;
 * sweep (at the end of lower_scene) drops what that lowering did not use. */
int lower_cache_find(lower_cache *c, const lower_options *o, const dev_prim *p, int n, bvh_tree *t);
void lower_cache_keep(lower_cache *c, const lower_options *o, const dev_prim *p, int n, const bvh_tree *t);
void lower_cache_sweep(lower_cache *c);

/* What --stats prints about one BVH. */
typedef struct {
	int mesh;           /* the scene mesh, or -1 for the top level */
	src_loc loc;
	int prims, nodes, leaves, depth;
	double sah_cost, build_ms;
	size_t bytes;       /* nodes, primitives and normals */
} lower_bvh_stats;

/* The buffers of the materials' patterns (lower_texture.c). */
typedef struct {
	dev_pattern *patterns;
	int n_patterns, cap_patterns;
	dev_warp *warps;
	int n_warps, cap_warps;
	dev_map_entry *maps;
	int n_maps, cap_maps;
	dev_image *images;        /* the scene's images (scene.images, in its order) */
	int n_images;
	float4 *texels;           /* theirs, in the working gamma */
	long n_texels;
	int see_through;          /* some colour has filter or transmit */
	int uses_uv;              /* some pattern is uv_mapped (SCENE_UV) */
	dev_material *subs;       /* the textures of texture_maps and the lower layers, until appended */
	int n_subs, cap_subs;
	dev_media *media;         /* the interiors' and the atmosphere's media (lower_media.c) */
	int n_media, cap_media;
	int *media_at;            /* a scene media chain's first dev_media, by its head, or -1 */
} lower_textures;

typedef struct {
	bvh_node *nodes;          /* the top level's, then each mesh's */
	int n_nodes;
	int layout;               /* the kernels' node layout, from lower_options */
	int kernels;              /* the entry points to build, from lower_options */
	bvh_wnode *wnodes;        /* the wide layout's nodes, the top level's root first; else NULL */
	int n_wnodes;             /* wide nodes, without the blocks */
	int n_wblocks;            /* blocks of four mesh triangles (bvh_tri4) in the same buffer */
	const void *dev_nodes;    /* what the kernels' node buffer holds: nodes or wnodes */
	size_t dev_node_bytes;
	dev_prim *prims;          /* the top level's in BVH order, the planes, then each mesh's;
	                           * an instance's link is its mesh's root in dev_nodes */
	int n_prims;              /* in the top level's BVH */
	int n_planes;             /* after them */
	int n_all_prims;
	float4 *normals;          /* three a smooth triangle */
	int n_normals;
	dev_material *materials;
	int n_materials;
	lower_textures textures;  /* the materials' patterns, warps and maps */
	int *object_flags;        /* OBJ_ flags, one per scene object */
	int n_objects;
	dev_light *lights;
	int n_lights;
	dev_fog *fogs;            /* the scene's fogs (lower_fog.c) */
	int n_fogs;
	dev_rainbow *rainbows;    /* the scene's rainbows (lower_rainbow.c) */
	int n_rainbows;
	float4 *camera_rays;      /* a mesh_camera's rays (lower_camera_mesh.c), the lens of focal
	                           * blur (lower_camera_lens.c), or NULL */
	long n_camera_rays;
	dev_emitter *emitters;    /* emissive primitives of the top level, with their power's cdf */
	int n_emitters;
	dev_sky sky;              /* the sky's importance sampling when params.sky_sampled (lower_sky.c) */
	float *sky_cdf;           /* its cdfs, or NULL */
	int n_sky_cdf;
	lower_bvh_stats *stats;   /* [0] the top level, then one per mesh placed */
	int n_stats;
	dev_params params;        /* camera and background; the renderer fills the rest */
	int function_levels;      /* lower_function_levels: FUNCTION_LEVELS when above 1 */
	int object_patterns;      /* some pattern is an object pattern: OBJECT_PATTERNS */
	char *functions;          /* the scene's functions as OpenCL C (lower_function.c), built
	                           * after the kernels' files; NULL when it has none */
} lower_result;

/* Returns 0, or -1 after printing errors against the objects' source lines. */
int lower_scene(const scene *s, const lower_options *opt, lower_result *out);
void lower_free(lower_result *r);

/* The scene's fogs into out->fogs (lower_fog.c); -1 when out of memory. */
int lower_fogs(const scene *s, lower_result *out);
/* The scene's rainbows into out->rainbows and params.n_rainbows, their
 * colour maps into lt; exits with a message on out of memory. */
void lower_rainbows(lower_textures *lt, const scene *s, lower_result *out);
/* The emitter table (lower_emitter.c): a row for each emitting primitive of
 * the top level that next-event estimation can sample, and its link to it;
 * -1 after saying that memory ran out. */
int lower_emitters(lower_result *r);
/* The sky's importance sampling (lower_sky.c): when the sky_sphere is one
 * spherical image_map, out->sky and out->sky_cdf, and params.sky_sampled set;
 * otherwise nothing, and the path tracer finds the sky by its bounce rays
 * alone. -1 after saying that memory ran out. */
int lower_sky(lower_result *out);
/* The distribution over an image of width x height whose texel (x, y), top
 * row first, has brightness weight[y * width + x] (>= 0), seen through rows
 * (the linear map from world directions to the image's, 3 x 4, the fourth
 * column ignored): the texels' weight times their solid angle. Returns 1 with
 * *sky and *cdf (malloc'ed, *n floats) made, 0 when there is nothing to
 * sample (no weight, or rows singular), -1 when out of memory. */
int lower_sky_table(const float *weight, int width, int height, const float rows[3][4], dev_sky *sky,
                    float **cdf, int *n);
/* A mesh_camera's rays for an image of width x height into out->camera_rays
 * (lower_camera_mesh.c); nothing for the other cameras. -1 after an error. */
int lower_camera_mesh(const scene *s, int width, int height, lower_result *out);
/* Cephes' chdtri, which POV-Ray's focal blur and media use for their confidence
 * tests: the x whose upper tail of the chi-square distribution with df degrees
 * of freedom is y (lower_camera_lens.c). */
double lower_chdtri(double df, double y);

/* The Whitted integrator's focal blur (lower_camera_lens.c): the lens's samples
 * and its confidence test's thresholds into out->camera_rays, when the camera
 * blurs (out->params.lens.x > 0; never a mesh_camera). -1 after an error. */
int lower_camera_lens(const scene *s, lower_result *out);
/* How many solid (non-hollow) objects hold the camera's location. */
int lower_camera_solids(const scene *s);

/* For an image with an alpha channel (+UA): how the background is seen then,
 * as POV-Ray sees it: by every ray but reflected ones, its colour times its
 * opacity (classic.x: its filter + transmit) and, in background.w, how much
 * of it is transparent (the kernels' alpha is 1 minus that where rays leave
 * the scene). */
void lower_background_alpha(const scene *s, dev_params *p);

/* The OpenCL build options for lr's kernels (the node layout is a -D, and
 * SCENE_FUNCTIONS says that lr->functions follows the kernels' files). */
const char *lower_kernel_options(const lower_result *lr);
/* The levels of functions the scene's run through function patterns
 * (scene_function_levels): lowering writes each function once a level, and
 * the kernels build with FUNCTION_LEVELS when there is more than one. */
int lower_function_levels(const scene *s);
/* The scene's functions as OpenCL C, or NULL when it has none (or on out of
 * memory, or after an error that a program is malformed). */
char *lower_function_source(const scene *s, const int *roots);
/* The same for a program whose kernel also reads pigment read as a level 1
 * function does (src/device_points.c's pattern_points): its function
 * patterns' functions at level 2, and as many levels as it needs
 * (FUNCTION_LEVELS: the larger of lower_function_levels and 1 +
 * scene_pigment_levels). read -1: none. */
char *lower_function_source_reading(const scene *s, const int *roots, int read);
/* 1 when function f's program keeps scene.h's promises; else 0, why in why. */
int lower_function_valid(const scene *s, int f, char *why, size_t n);

/* The media chain whose head is scene.media[head - 1] (0: none) as dev_media
 * records in lt, once however many materials hold it; their densities are
 * placed by to_world. Returns the first, and the count in *n. */
int lower_media(lower_textures *lt, const scene *s, int head, const xform *to_world, int *n);
/* Warns about media in objects that have no inside (a triangle, a mesh, a disc). */
void lower_media_warn_open(const scene *s);
/* Pattern pigment pigment of the pool flattened into lt with no transformation
 * around it, for a pattern or pigment function: its first dev_pattern. */
int lower_texture_pigment(lower_textures *lt, const scene *s, int pigment);
/* Each scene pigment's dev_pattern in lt for the functions that call it
 * (lower_texture_pigment), -1 for the others; NULL when none does. */
int *lower_function_roots(lower_textures *lt, const scene *s);
/* A density { }'s material (its pigment: the density) in lt->subs, placed by to_world. */
int lower_texture_density(lower_textures *lt, const scene *s, int pattern, const float rgb[3],
                          const xform *to_world);

/* A POV-Ray texture and interior as the kernels read them (ambient multiplied
 * by ambient_light); its pattern pigments go into lt. local: a mesh's own
 * texture, whose patterns are in the mesh's space. */
dev_material lower_texture(lower_textures *lt, const scene *s, const scene_material *m, int local);
/* The material of a blob whose components have textures of their own
 * (MATERIAL_BLOB): own, the blob's material, with a map whose entries are
 * the components' textures in order (own's for those without one), placed
 * in the blob's space, with the blob's interior, then own's. */
dev_material lower_texture_blob(lower_textures *lt, const scene *s, const scene_object *o, const dev_material *own);
/* The material of m's interior_texture (m->interior_texture > 0), with m's interior. */
dev_material lower_interior_texture(lower_textures *lt, const scene *s, const scene_material *m);
/* Appends the materials of texture_maps' entries and lower layers (lt->subs)
 * after *mats, and makes the references to them indices into *mats. */
void lower_textures_append(lower_textures *lt, dev_material **mats, int *n_mats);
void lower_textures_free(lower_textures *lt);
/* The tree over a CSG object's first n leaf boxes (lowering's box records,
 * those of the leaves rays may meet), as shared.h's CSG record
 * has it: its nodes in a new array and how many, its list of leaves (n ints,
 * which the runs of leaves index) and its root's reference in *root; free()
 * the arrays. *root is CSG_NO_TREE where a tree would not pay (then the
 * arrays are NULL). Returns the tree's depth, which the kernels' stack
 * (CSG_TREE_STACK) must hold (lower_csg_tree.c). */
int lower_csg_tree(const dev_prim *boxes, int n, dev_prim **nodes, int *n_nodes, int **list, int *root);
/* A CSG object's program (CSG_LEAF_BOXED for the leaves whose insides lie
 * within their boxes) as the kernels run it, into *out: its chains rebalanced
 * and CSG_SKIP before the parts the kernels may skip (lower_csg_program.c);
 * boxes: the leaves' box records, the first n_seen those of the leaves rays
 * may meet (the leaf tree's). Returns its depth (more than CSG_STACK: keep ops). */
int lower_csg_program(const int *ops, int n, const dev_prim *boxes, int n_seen, csg_prog *out);
/* The inverse of an affine transform; -1 when it is singular. */
int lower_invert(const xform *t, xform *inv);

#endif
