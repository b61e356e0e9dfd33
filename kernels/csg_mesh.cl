/* csg_mesh.cl: a mesh as a CSG's leaf (PRIM_CSG_MESH, shared.h): a mesh, a
 * height field, a parametric surface or a bicubic patch, which eclat makes
 * into triangles. Its hits come from its own BVH in its own space, as an
 * instance's do; it is inside where POV-Ray's Mesh::Inside says: an odd number
 * of crossings along its inside_vector (a height field: upward, which is
 * POV-Ray's HField::Inside away from water_level). A mesh without one has no
 * inside, and, as POV-Ray's mesh and parametric give a CSG only their nearest
 * intersection, offers only its nearest hit past the ray's start. Declared in
 * csg.cl; here, after traverse.cl, since csg.cl comes before the traversal. */

static float csg_mesh_intersect(global const bvh_node *nodes, global const dev_prim *prims,
                                global const dev_prim *leaf, float3 o, float3 d, float start, float t, float tmax,
                                int *tri, uint *counts, int kind)
{
	global const dev_prim *rec = &prims[leaf->link];
	bool solid = any(rec->a.xyz != (float3)(0.0f));
	float3 mo = intersect_to_local(leaf, o), md = intersect_dir_to_local(leaf, d);
	traverse_hit h = traverse_mesh(0, nodes, prims, as_int(rec->a.w), mo, md, solid ? t : start, tmax, false, counts,
	                               kind);
	if (h.prim < 0 || h.t <= t)   /* none, or (with no inside) its nearest is behind */
		return tmax;
	*tri = h.prim;
	return h.t;
}

static bool csg_mesh_inside(global const bvh_node *nodes, global const dev_prim *prims, global const dev_prim *leaf,
                            float3 x, uint *counts, int kind)
{
	global const dev_prim *rec = &prims[leaf->link];
	float3 v = rec->a.xyz;
	if (!any(v != (float3)(0.0f)))
		return false;
	float3 mx = intersect_to_local(leaf, x);
	uint n = 0;
	float t = 0.0f;
	for (int c = 0; c < CSG_CROSSINGS; c++) {   /* hits at one distance (an edge's two triangles) count once */
		traverse_hit h = traverse_mesh(0, nodes, prims, as_int(rec->a.w), mx, v, t, INFINITY, false, counts, kind);
		if (h.prim < 0)
			break;
		n++;
		t = h.t;
	}
	return (n & 1u) != 0u;
}
