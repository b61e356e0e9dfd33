/* lower.h: the scene flattened into the buffers the kernels read, plus its BVHs:
 * one for the top level (the scene's primitives and one instance per placed
 * mesh) and one per mesh, stored once however often the mesh is placed. */
#ifndef ECLAT_LOWER_H
#define ECLAT_LOWER_H

#include <stddef.h>

#include "../kernels/shared.h"
#include "bvh.h"
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
} lower_options;

/* What --stats prints about one BVH. */
typedef struct {
	int mesh;           /* the scene mesh, or -1 for the top level */
	src_loc loc;
	int prims, nodes, leaves, depth;
	double sah_cost, build_ms;
	size_t bytes;       /* nodes, primitives and normals */
} lower_bvh_stats;

typedef struct {
	bvh_node *nodes;          /* the top level's, then each mesh's */
	int n_nodes;
	int layout;               /* the kernels' node layout, from lower_options */
	bvh_wnode *wnodes;        /* the wide layout's nodes, the top level's root first; else NULL */
	int n_wnodes;
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
	dev_finish *finishes;     /* the same textures for the Whitted integrator, one per material */
	int n_materials;
	int *object_flags;        /* OBJ_ flags, one per scene object */
	int n_objects;
	dev_light *lights;
	int n_lights;
	dev_emitter *emitters;    /* emissive primitives of the top level, with their power's cdf */
	int n_emitters;
	lower_bvh_stats *stats;   /* [0] the top level, then one per mesh placed */
	int n_stats;
	dev_params params;        /* camera and background; the renderer fills the rest */
} lower_result;

/* Returns 0, or -1 after printing errors against the objects' source lines. */
int lower_scene(const scene *s, const lower_options *opt, lower_result *out);
void lower_free(lower_result *r);

/* The OpenCL build options for lr's kernels (the node layout is a -D). */
const char *lower_kernel_options(const lower_result *lr);

/* The physically based material of a POV-Ray texture and interior. */
dev_material lower_material(const scene_material *m);
/* The same texture and interior as POV-Ray's classic model reads them; ambient
 * is multiplied by ambient_light. */
dev_finish lower_finish(const scene_material *m, const float ambient_light[3]);

#endif
