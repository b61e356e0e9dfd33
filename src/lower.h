/* lower.h: the scene flattened into the buffers the kernels read, plus its BVH. */
#ifndef ECLAT_LOWER_H
#define ECLAT_LOWER_H

#include "../kernels/shared.h"
#include "bvh.h"
#include "scene.h"

typedef struct {
	dev_prim *prims;          /* BVH leaf order, then the planes */
	int n_prims;              /* in the BVH */
	int n_planes;             /* after them */
	dev_material *materials;
	int n_materials;
	dev_light *lights;
	int n_lights;
	dev_emitter *emitters;    /* emissive primitives, with their power's cdf */
	int n_emitters;
	bvh_tree bvh;
	dev_params params;        /* camera and background; the renderer fills the rest */
} lower_result;

/* Returns 0, or -1 after printing errors against the objects' source lines. */
int lower_scene(const scene *s, lower_result *out);
void lower_free(lower_result *r);

/* The physically based material of a POV-Ray texture and interior (exported for tests). */
dev_material lower_material(const scene_material *m);

#endif
