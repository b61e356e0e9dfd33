/* traverse.cl: closest-hit and any-hit traversal of the binary BVH (bvh_node,
 * shared.h): a stack of node indices, the nearer child first, far nodes pruned
 * against the closest hit so far. The host guarantees the tree is no deeper than
 * BVH_STACK_SIZE, so the stack cannot overflow. */

/* Slab test. inv_d may hold infinities (axis-parallel rays); fmin and fmax drop
 * the NaN of 0 * inf, so a ray lying in a slab's plane is not lost. Returns the
 * entry distance, or INFINITY when the box is missed or farther than tmax. */
inline float traverse_box(global const bvh_node *n, float3 o, float3 inv_d, float tmax)
{
	float3 t1 = ((float3)(n->min_x, n->min_y, n->min_z) - o) * inv_d;
	float3 t2 = ((float3)(n->max_x, n->max_y, n->max_z) - o) * inv_d;
	float3 lo = fmin(t1, t2), hi = fmax(t1, t2);
	float enter = fmax(fmax(lo.x, lo.y), fmax(lo.z, 0.0f));
	float leave = fmin(fmin(hi.x, hi.y), fmin(hi.z, tmax));
	return enter <= leave ? enter : INFINITY;
}

typedef struct {
	float t;
	int prim;      /* -1: no hit */
} traverse_hit;

/* Closest hit in (tmin, tmax). tests counts box and primitive tests (the heat map). */
inline traverse_hit traverse_closest(global const bvh_node *nodes, global const dev_prim *prims,
                                     int n_prims, float3 o, float3 d, float tmin, float tmax,
                                     uint *tests)
{
	traverse_hit hit = { tmax, -1 };
	if (n_prims == 0)
		return hit;
	float3 inv_d = 1.0f / d;
	int stack[BVH_STACK_SIZE], sp = 0, node = 0;
	*tests += 1;
	if (traverse_box(&nodes[0], o, inv_d, hit.t) == INFINITY)
		return hit;
	for (;;) {
		global const bvh_node *n = &nodes[node];
		if (n->count > 0) {
			for (int i = n->left_first; i < n->left_first + n->count; i++) {
				float t = intersect_prim(o, d, &prims[i], tmin, hit.t);
				*tests += 1;
				if (t < hit.t) {
					hit.t = t;
					hit.prim = i;
				}
			}
		} else {
			int a = n->left_first, b = a + 1;
			float ta = traverse_box(&nodes[a], o, inv_d, hit.t);
			float tb = traverse_box(&nodes[b], o, inv_d, hit.t);
			*tests += 2;
			if (ta > tb) {
				float tt = ta; ta = tb; tb = tt;
				int ti = a; a = b; b = ti;
			}
			if (ta != INFINITY) {
				if (tb != INFINITY)
					stack[sp++] = b;
				node = a;
				continue;
			}
		}
		/* pop the next node still nearer than the closest hit */
		for (;;) {
			if (sp == 0)
				return hit;
			node = stack[--sp];
			if (traverse_box(&nodes[node], o, inv_d, hit.t) != INFINITY)
				break;
		}
	}
}

/* Any hit in (tmin, tmax): shadow rays stop at the first occluder. */
inline bool traverse_any(global const bvh_node *nodes, global const dev_prim *prims, int n_prims,
                         float3 o, float3 d, float tmin, float tmax, uint *tests)
{
	if (n_prims == 0)
		return false;
	float3 inv_d = 1.0f / d;
	int stack[BVH_STACK_SIZE], sp = 0;
	stack[sp++] = 0;
	while (sp > 0) {
		global const bvh_node *n = &nodes[stack[--sp]];
		*tests += 1;
		if (traverse_box(n, o, inv_d, tmax) == INFINITY)
			continue;
		if (n->count > 0) {
			for (int i = n->left_first; i < n->left_first + n->count; i++) {
				*tests += 1;
				if (intersect_prim(o, d, &prims[i], tmin, tmax) < tmax)
					return true;
			}
		} else {
			stack[sp++] = n->left_first + 1;
			stack[sp++] = n->left_first;
		}
	}
	return false;
}
