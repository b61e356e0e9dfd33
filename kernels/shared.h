/* shared.h: every struct that crosses the host/device boundary, and nothing else.
 *
 * Included by the host (C11) and prepended to the OpenCL program. Layouts are
 * built from 16-byte groups padded by hand; the host checks each size and offset
 * with _Static_assert (src/lower.c). No float3, bool, size_t or pointers: their
 * sizes differ between host and device. */
#ifndef ECLAT_SHARED_H
#define ECLAT_SHARED_H

#ifndef __OPENCL_VERSION__
typedef unsigned int uint;
/* The host's float4 has the device's size, alignment and member names. */
typedef struct { float x, y, z, w; } __attribute__((aligned(16))) float4;
#endif

/* One node of the binary BVH, 32 bytes (pbrt's LinearBVHNode, tinybvh's layout).
 * Interior node (count == 0): children are nodes[left_first] and nodes[left_first + 1].
 * Leaf (count > 0): primitives prims[left_first .. left_first + count - 1]. */
typedef struct {
	float min_x, min_y, min_z;
	int left_first;
	float max_x, max_y, max_z;
	int count;
} bvh_node;

/* The traversal kernels keep a stack of this many nodes; the host refuses a
 * deeper tree rather than let a ray silently miss. */
#define BVH_STACK_SIZE 64

/* One node of the 4-wide BVH, 64 bytes, converted from the binary tree
 * (src/bvh_wide.c; eclat(1), --bvh-layout). Up to four children, each given
 * by its box, quantized to 8 bits per side on a grid of steps 2^e from the
 * node's lower corner: child k's box on x is origin_x + q * 2^e_x for q = byte k
 * of qlo_x and of qhi_x. The host rounds each bound outwards and checks it
 * with the float arithmetic the device uses (q * 2^e is exact), so a
 * dequantized box always contains the child.
 * meta: bytes 0-2, the biased exponents e + 127 of x, y, z (the bits of the
 *   float 2^e when shifted left by 23); byte 3, the number of children (0-4).
 * child[k] >= 0: an interior child, the index of its wide node; < 0: a leaf,
 *   bits 0-25 its first primitive, bits 26-30 its primitive count (1-31).
 *   In a mesh's tree (not the top level's) bits 0-25 are instead the node
 *   index of the leaf's first bvh_tri4 block, and its count triangles are in
 *   (count + 3) / 4 blocks from there.
 * With --bvh-layout wide the kernels' node buffer holds these; it keeps the
 * type bvh_node in every signature and only traverse.cl reads it. */
typedef struct {
	float origin_x, origin_y, origin_z;
	uint meta;
	uint qlo_x, qhi_x, qlo_y, qhi_y, qlo_z, qhi_z;
	int child[4];
	int pad[2];
} bvh_wnode;
#define BVH_WIDE_LEAF_MAX 31
#define BVH_WIDE_FIRST_BITS 26

/* Four of a wide mesh leaf's triangles, their corners a, b, c in
 * structure-of-arrays (ax holds the four corners a's x), so that one work item
 * tests the four together in float4s (traverse.cl, traverse_blocks); 192 bytes,
 * three node slots, in the node buffer beside the nodes that point at them
 * (src/bvh_wide.c). prim: each triangle's index in the primitives, which the
 * hit reports and shading reads; lanes past the leaf's count hold -1 and
 * zeros. The corners are copies of the primitives', bit for bit. */
typedef struct {
	float4 ax, ay, az, bx, by, bz, cx, cy, cz;
	int prim[4];
	int pad[8];
} bvh_tri4;
#define BVH_TRI4_SLOTS 3   /* node slots a block takes */

/* The device's shapes, one row each: X(NAME, name) makes PRIM_NAME and calls
 * name_intersect, name_normal and name_inside, which kernels/shape_*.cl define
 * (kernels/shape.cl dispatches on the row; src/shape.h says how a new shape is
 * added); an S row's functions take the scene's buffers first (an isosurface's
 * function may call the scene's pattern and pigment functions). The order is
 * the numbering; the kinds after the table are not shapes a ray meets by
 * itself. */
#define PRIM_SHAPES(X, S) \
	X(TRIANGLE, triangle) \
	X(SPHERE, sphere) \
	X(PLANE, plane) \
	X(ELLIPSOID, ellipsoid) \
	X(SMOOTH_TRIANGLE, smooth_triangle) \
	X(BOX, box) \
	X(PRISM, prism) \
	X(QUADRIC, quadric) \
	X(SOR, sor) \
	X(CYLINDER, cylinder) \
	X(CONE, cone) \
	X(DISC, disc) \
	X(TORUS, torus) \
	X(SUPERELLIPSOID, superellipsoid) \
	S(ISOSURFACE, isosurface) \
	X(POLY, poly) \
	X(BLOB, blob) \
	X(JULIA_FRACTAL, julia_fractal) \
	X(SPHERE_SWEEP, sphere_sweep)
/* The shapes that can be sampled for next-event estimation when they emit:
 * each has name_emit_sample and name_emit_pdf in its kernel file, and its area
 * in src/lower_emitter.c; other emitting shapes are found by rays alone. */
#define PRIM_EMITTERS(X) \
	X(TRIANGLE, triangle) \
	X(SPHERE, sphere) \
	X(DISC, disc) \
	X(CYLINDER, cylinder)
#define PRIM_ENUM_ROW(NAME, name) PRIM_##NAME,
enum {
	PRIM_SHAPES(PRIM_ENUM_ROW, PRIM_ENUM_ROW)
	PRIM_INSTANCE,   /* a placed mesh: traverse.cl walks the mesh's BVH */
	PRIM_CSG,        /* a CSG object: kernels/csg.cl classifies its leaves' hits */
	PRIM_DATA,       /* numbers of the record before it, never hit by itself */
	PRIM_CSG_MESH,   /* a placed mesh as a CSG's leaf: csg.cl walks the mesh's BVH */
};

/* A julia_fractal's algebra and function (src/shape_julia_fractal.c). */
enum { JULIA_QUATERNION = 0, JULIA_HYPERCOMPLEX = 1 };
enum { JULIA_SQR = 0, JULIA_CUBE = 1 };

/* A prism's flags (polygon, prism and text: src/prism.h): no caps, one flat
 * face (a polygon: no sides, no inside), conic_sweep. */
enum { PRISM_OPEN = 1, PRISM_FLAT = 2, PRISM_CONIC = 4 };

/* A primitive, 64 bytes. The BVH is two-level: the top level holds the scene's
 * primitives in world space and one instance per placed mesh; each mesh has a
 * BVH of its own over its triangles in object space, stored once however many
 * times it is placed.
 * Triangle: a, b, c = its corners, as given: neighbours must see bit-identical
 *   shared corners for the watertight test;
 *   link: index into the emitter table when it emits (top level only), else -1.
 * Smooth triangle: as a triangle; link: its three normals in the normals buffer
 *   (normals[3 * link ...]); when the first normal's w is 1, its corners' uv
 *   follow as three more (xy), for uv_mapping (a mesh's triangles with uv are
 *   all smooth: a flat one's normals are its face's).
 * Sphere: a.xyz = centre, a.w = radius; link as for a triangle.
 * Plane: a.xyz = unit normal, a.w = distance along it; planes are unbounded, so
 *   they sit after the top level's primitives and every ray tests them all.
 * Shapes in a space of their own (ellipsoid: the unit sphere; box: the cube
 *   [-1, 1]^3; the others as their kernel file says) and instances: a, b, c are
 *   the rows of the affine map from world space to that space (for an instance,
 *   the mesh's); the ray keeps its parameter t there. For such a shape, link is
 *   its PRIM_DATA record (its own numbers in a), or -1 when it needs none; for an
 *   instance, the root node of the mesh's BVH. A record's own link is -1, but
 *   for the first record of an emitting disc or cylinder of the top level: its
 *   index into the emitter table.
 * Torus: the map to the torus of major radius 1 around the y axis; its record's
 *   a.x is the minor radius over the major one (kernels/shape_torus.cl).
 * Superellipsoid: the map to its own space, where it fills [-1, 1]^3; its
 *   record's a.x + a.y is 2/E, a.z + a.w 2/N (kernels/shape_superellipsoid.cl).
 * Isosurface: the map to its own space; three records: its container, function,
 *   threshold, accuracy, max_gradient, max_trace and flags (kernels/shape_isosurface.cl).
 * Blob: the map to its own space; its first record's a.x is its number of
 *   components, a.y its threshold; each component then two records: a.xyz one
 *   end (the centre) and a.w the radius, b.xyz the other end and b.w the
 *   strength, c.x 1 when the component has a space of its own, whose map from
 *   the blob's is the second record's rows a, b, c (kernels/shape_blob.cl).
 * Julia fractal: the map to its own space; four records: a the constant c,
 *   the slice (unit length), then slice distance, 1/precision, exit value and
 *   bounding radius, then max_iteration, algebra and function as floats
 *   (JULIA_; kernels/shape_julia_fractal.cl).
 * Sphere sweep: the map to its own space, about the centre of its box; a
 *   head record (a.x its number of segments, a.y its tolerance, a.z the depth
 *   below which a point counts as on its surface), six records a segment
 *   (its box's corners, and the coefficients of u^0 to u^3 of its centre
 *   (xyz) and radius (w)), then a record a primitive: a few segments each
 *   (a.x the first, a.y how many, a.z how many records back the head is),
 *   linked from it (kernels/shape_sphere_sweep.cl).
 * Poly (poly, cubic, quartic, polynomial): the map to its own space; its first
 *   record's a.x is its order, and the records after it hold its coefficients
 *   in POV-Ray's order, two in each a, each as a float and the float of what
 *   it leaves, so that the device may add them in double
 *   (kernels/shape_poly.cl).
 * CSG: a.x, a.y (ints): its first leaf and how many; a.z, a.w (ints): its
 *   program's first record and its length in ops (kernels/csg.cl); link: how
 *   many of its leaves rays may meet (the rest are clipped_by's, which only
 *   answer inside tests); b.x (int): its first leaf box record (PRIM_DATA, one
 *   a leaf: a.xyz, b.xyz its padded bounds, a.w 1 when the leaf's inside lies
 *   within them; kernels/csg.cl's csg_box); b.y, b.z, b.w (ints): the tree
 *   over the boxes of the leaves rays may meet (src/lower_csg_tree.c): its
 *   first node record, its root (CSG_NO_TREE: none, the kernels loop over
 *   the leaves) and its list of leaves' first record (ints,
 *   CSG_OPS_PER_RECORD in a record's a, b and c). A reference in the tree is
 *   a node (>= 0, counted from b.y) or a leaf k (~k, whose box is its box
 *   record). A node's record: a.xyz and b.xyz its box, c.x and c.y (ints) its
 *   two children; or, when c.w (int) is not 0, a run of c.w leaves, those of
 *   the list from c.z on, in the leaves' order. The leaves, the program's
 *   records (PRIM_DATA, CSG_OPS_PER_RECORD ops each in a, b and c), the boxes
 *   and the tree are after every BVH's primitives, where no BVH points.
 * CSG mesh: a mesh (height field, parametric...) as a CSG's leaf: as an
 *   instance, but link is its PRIM_DATA record: a.xyz the direction in the
 *   mesh's space along which crossings are counted for its inside (POV-Ray's
 *   inside_vector; 0: it has no inside and offers only its nearest hit),
 *   a.w (int) the root of the mesh's BVH (kernels/csg_mesh.cl).
 * material: -1 in a mesh's triangle without a texture of its own: the instance's.
 * object: the scene object's number (-1 in a mesh: the instance's). */
typedef struct {
	float4 a, b, c;
	int type, material, object, link;
} dev_prim;

/* A CSG program's ops (kernels/csg.cl): each an int, the op in the top 8 bits
 * and its operand below. CSG_LEAF k pushes whether the point is inside leaf k;
 * CSG_NOT inverts the top; CSG_AND n, CSG_OR n (merge) and CSG_UNION n (a union,
 * which keeps its parts' inner surfaces) combine the top n. Lowering writes
 * CSG_LEAF_BOXED k for a leaf whose inside lies within its box (its box
 * record's a.w), so that the kernels answer it outside where the leaf tree
 * says the point is outside that box, without reading its record; and
 * CSG_SKIP (n << 1 | v) before a part of n ops whose leaves are all such,
 * followed by two ints, the low and high halves of the 64-bit mask of its
 * leaves (bit k % 64 for leaf k): when no leaf of the mask is the one
 * classified or has a box that holds the point, each is outside, and the part
 * is v (src/lower_csg_program.c). */
enum { CSG_LEAF = 1, CSG_NOT = 2, CSG_AND = 3, CSG_OR = 4, CSG_UNION = 5, CSG_LEAF_BOXED = 6, CSG_SKIP = 7 };
#define CSG_OP_SHIFT 24
#define CSG_OPS_PER_RECORD 12   /* a, b and c of a PRIM_DATA record */
#define CSG_STACK 32   /* the deepest a program may nest; lowering checks it */
#define CSG_TREE_STACK 32   /* the deepest a CSG's leaf tree may be; lowering checks it */
#define CSG_NO_TREE (-0x7fffffff - 1)   /* a CSG record's root when it has no leaf tree */

/* A surface's material, 208 bytes, one per texture: POV-Ray's finish and
 * interior as the scene gives them (lower.c changes nothing but ambient, which
 * is multiplied by global_settings' ambient_light), and its pigment: a solid
 * colour, or a pattern evaluated at each shading point (texture.cl). Both
 * integrators read it: the Whitted one as POV-Ray's classic model, the path
 * tracer through material_bsdf (material.cl), which maps it onto a layered
 * BSDF as eclat-scene(5), HOW MATERIALS ARE RENDERED, says.
 * A layered texture is its top layer's material, whose below is the next
 * layer down (-1: the bottom). A pattern of whole textures (texture_map,
 * checker texture { } texture { }) is a material with MATERIAL_TEXTURE_MAP:
 * its pattern picks or blends the materials of its map's entries
 * (dev_map_entry.material) at each point (texture_blend_at); its pigment is
 * their average, its finish the first's, for what needs one colour. Every
 * material of a surface holds the object's interior. */
typedef struct {
	float4 pigment;        /* rgb; w: filter (with a pattern: its average colour) */
	float4 ambient;        /* rgb: ambient * ambient_light; w: transmit */
	float4 emission;       /* rgb; w: diffuse */
	float4 highlight;      /* x: phong, y: phong_size, z: specular, w: 1 / roughness */
	float4 reflection;     /* rgb: reflection at normal incidence (min); w: falloff */
	float4 reflection_max; /* rgb: at grazing incidence (max); w: 1 / exponent */
	float4 terms;          /* x: brilliance, y: metallic (highlights), z: reflection's metallic,
	                        * w: 1 for fresnel reflection */
	float4 interior;       /* x: ior, y: fade_distance, z: fade_power, w: 1 for conserve_energy */
	float4 fade_color;     /* rgb: interior's fade_color */
	int pattern;           /* the pigment's dev_pattern, or -1: the solid pigment above */
	int flags;             /* MATERIAL_ */
	int normal;            /* the normal's dev_pattern (pattern_perturb), or -1: none */
	int below;             /* a layered texture's next layer down, or -1 */
	int media, n_media;    /* the interior's dev_media records (media, media + 1, ...); the
	                        * first also names the interior for the rays inside it */
	int noise_generator;   /* global_settings': irid's turbulence */
	int pad;
	float4 irid;           /* x: irid's amount (0: none), y: its film thickness, z: its turbulence;
	                        * w: crand */
	float4 irid_wavelength; /* rgb: global_settings' irid_wavelength; w: the interior's caustics
	                        * power (POV-Ray's: 45 times the amount written; 0: none) */
} dev_material;
/* MATERIAL_LOCAL: a mesh's own texture, whose patterns see the mesh's space;
 * MATERIAL_ROUGH: roughness was given, so the path tracer's reflection is rough;
 * MATERIAL_TEXTURE_MAP: pattern is a pattern of whole textures;
 * MATERIAL_INTERIOR: the object has an interior_texture, the next material,
 * for the side its surface normal turns away from (texture_point);
 * MATERIAL_BLOB (with MATERIAL_TEXTURE_MAP): a blob whose components have
 * textures of their own: its pattern's map entries are the components'
 * textures, in the blob's order, weighted by the components' fields at the
 * point, not picked by a value (texture_blend_at), then the blob's own. */
enum { MATERIAL_LOCAL = 1, MATERIAL_ROUGH = 2, MATERIAL_TEXTURE_MAP = 4, MATERIAL_INTERIOR = 8, MATERIAL_BLOB = 16 };

/* ---- Appearance: patterns, maps and pigments (kernels/pattern.cl, kernels/texture.cl).
 *
 * A pattern maps a point in its own space to a value (pattern_value); the value
 * picks a colour, or blends two, from a map (dev_map_entry). Continuous patterns
 * (gradient, bozo, wood...) give a value in [0, 1] after turbulence, frequency,
 * phase and wave type; POV-Ray's discrete patterns (checker, hexagon, brick,
 * cubic, square, triangular) give the index of a list entry: 0, 1, 2... as a float.
 * The numbers are POV-Ray 3.7's: a mask of a pattern renders POV-Ray's pixels. */
enum {                       /* ORDER: the names in src/eval_pattern.c */
	PATTERN_SOLID = 0,   /* no pattern: the map's first entry */
	PATTERN_AGATE, PATTERN_AOI, PATTERN_BOXED, PATTERN_BOZO, PATTERN_BRICK,
	PATTERN_BUMPS, PATTERN_CELLS, PATTERN_CHECKER, PATTERN_CRACKLE, PATTERN_CUBIC,
	PATTERN_CYLINDRICAL, PATTERN_DENTS, PATTERN_FACETS, PATTERN_GRADIENT, PATTERN_GRANITE,
	PATTERN_HEXAGON, PATTERN_LEOPARD, PATTERN_MARBLE, PATTERN_ONION, PATTERN_PLANAR,
	PATTERN_QUILTED, PATTERN_RADIAL, PATTERN_RIPPLES, PATTERN_SPHERICAL, PATTERN_SPIRAL1,
	PATTERN_SPIRAL2, PATTERN_SPOTTED, PATTERN_SQUARE, PATTERN_TRIANGULAR, PATTERN_WAVES,
	PATTERN_WOOD, PATTERN_WRINKLES,
	PATTERN_IMAGE_MAP,   /* a colour, not a value: texture.cl's texture_image */
	PATTERN_FUNCTION,    /* function { }: the scene's function params[0].x (function.cl) */
	PATTERN_AVERAGE,     /* no value: every map entry, weighted by its value (texture.cl) */
	PATTERN_SLOPE,       /* of the shading normal, and of the altitude (pattern.cl) */
	PATTERN_MANDEL, PATTERN_JULIA, PATTERN_MAGNET,   /* kernels/pattern_fractal.cl */
	PATTERN_IMAGE_PATTERN,   /* an image's grey (or alpha) as the value: image.cl */
	PATTERN_BUMP_MAP,    /* a normal only, from an image's greys: image.cl */
	PATTERN_MATERIAL_MAP,   /* a texture's: an image's material numbers pick textures: image.cl */
	PATTERN_DENSITY_FILE,   /* a df3 file's voxels in the unit cube: image.cl */
	PATTERN_TILING,      /* POV-Ray's 27 tilings of the x-z plane: kernels/pattern_tiling.cl */
	PATTERN_PAVEMENT,    /* POV-Ray's pavings by polyforms: kernels/pattern_pavement.cl */
	PATTERN_OBJECT,      /* 1 inside an object, 0 outside: its CSG record (csg.cl) */
	PATTERN_COUNT
};
/* POV-Ray's wave types, applied to a continuous pattern's value. */
enum { WAVE_RAMP = 0, WAVE_SINE, WAVE_TRIANGLE, WAVE_SCALLOP, WAVE_CUBIC, WAVE_POLY };
/* Warps, applied in order to the point before the pattern (dev_warp). */
enum { WARP_TURBULENCE = 0, WARP_REPEAT, WARP_BLACK_HOLE, WARP_TRANSFORM, WARP_PLANAR, WARP_CYLINDRICAL,
       WARP_SPHERICAL, WARP_TOROIDAL, WARP_CUBIC };

/* One warp, 80 bytes. A pattern's warps are in POV-Ray's list order, which is
 * the order they apply in: each warp { } written goes to the FRONT of the list
 * (the last written applies first); the turbulence written in the pattern
 * itself goes to the END when first written, and stays last; a transformation
 * joins the front entry when that is a transformation, else becomes a new
 * front entry. The front transformation is dev_pattern.rows; one written
 * before a warp { } that follows it is a WARP_TRANSFORM entry.
 * turbulence: a.xyz turbulence, a.w omega; b.x lambda, b.y octaves (1-10);
 *   classic = 1 for the turbulence written in the pattern (turbulence, octaves,
 *   omega, lambda outside a warp { }: POV-Ray's "classic" turbulence), 0 for
 *   warp { turbulence }. Marble and wood never apply the classic one as a warp;
 *   agate, marble, spiral1, spiral2 and wood read its parameters. Agate always
 *   has one: POV-Ray creates it, turbulence 0.
 * repeat: a.xyz the repeat vector (one non-zero component: the axis and the
 *   width); b.xyz offset; c.xyz flip (non-zero: flip that axis).
 * black_hole: a.xyz centre, a.w radius; b.x strength, b.y falloff,
 *   b.z 1 for inverse; c.xyz repeat, c.w 1 when repeated; centre and repeat as
 *   POV-Ray adjusts them for a repeat (Check_BH_Parameters); d.xyz its
 *   turbulence, how far each repeated hole's centre moves at random (POV-Ray's
 *   uncertainty vector); a type other than 0 is not kept (it does nothing in
 *   3.7: drop the warp).
 * transform: a, b, c the rows of the affine map applied to the point (the
 *   inverse of the transformation written), as dev_pattern.rows.
 * planar, cylindrical, spherical, toroidal, cubic: POV-Ray 3.7's mapping
 *   warps, which take a plane, a cylinder, a sphere, a torus or a cube's
 *   surface to the xy plane (warps.cpp); a.xyz the orientation (unit; <0, 0, 1>
 *   by default), a.w dist_exp (planar: its offset), b.x a torus's major radius. */
typedef struct {
	float4 a, b, c, d;
	int kind, classic, pad1, pad2;
} dev_warp;

/* A pattern with its modifiers, 144 bytes. A pigment's pattern (texture.cl)
 * or a normal's (normal.cl, pattern_perturb: POV-Ray's normal { PATTERN
 * [Amount] }).
 * bump_size: a normal's Amount or bump_size (POV-Ray's default 0.5); unused by pigments.
 * normal: a normal's x: accuracy (POV-Ray's default 0.02); slope's y, z: the
 *   altitude's range, low and width (0: none); w: 0.
 * A normal's map entries are its slope_map (none: map_count 0): value, the
 *   entry's key; colour.x, the height; colour.y, the slope. normal_map (nested
 *   normals) is not supported.
 * rows: the affine map from world space to the pattern's space (the inverse of
 *   the transformations written after the pattern and around the texture).
 *   POV-Ray applies them before every warp, except a transformation written
 *   before a warp { } (see dev_warp).
 * noise_generator: 1, 2 or 3, the pattern's or global_settings' (default 2).
 * frequency 0 skips frequency and phase: POV-Ray's default for quilted (and for
 *   the discrete patterns, which ignore frequency, phase and wave anyway).
 *   Marble, wood, spiral1 and spiral2 default to the triangle wave.
 * flags: PATTERN_NO_BUMP_SCALE (normals: no_bump_scale).
 * params, by kind (POV-Ray's defaults filled in by the host):
 *   agate:     params[0].x agate_turb (1)
 *   brick:     params[0].xyz brick_size (<8, 3, 4.5>), w mortar (0.5)
 *   crackle:   params[0].xyz form (<-1, 1, 0>), w metric (2); params[1].x offset (0),
 *              y 1 for solid
 *   gradient:  params[0].xyz the axis vector, normalized (as POV-Ray does)
 *   quilted:   params[0].x control0 (1), y control1 (1)
 *   spiral1/2: params[0].x the number of arms
 *   waves, ripples: params[0].x global_settings' number_of_waves (10), filled
 *              in by lowering
 *   tiling:    params[0].x the tiling's number, 1 to 27
 *   pavement:  params[0].x number_of_sides (3, 4, 6), y number_of_tiles, z pattern,
 *              w form; params[1].x interior, y exterior (checked and reduced as
 *              POV-Ray does: src/eval_pattern.c)
 *   facets:    params[0].x size (0.1), y coords (0: none, the normal's own facets),
 *              z metric (2) (a normal only)
 *   image_map: params[0].x the image (dev_image), y map_type (0 planar,
 *              1 spherical, 2 cylindrical, 5 torus), z interpolate (0 none,
 *              2 bilinear, 4 normalized distance), w 1 for once;
 *              params[1].x filter all, y transmit all; no map
 *   image_pattern, bump_map: params[0] as image_map's; image_pattern's
 *              params[1].x 1 for use_alpha, y 1 when the image has an alpha
 *              channel; bump_map's bump_size its amount
 *   material_map: params[0] as image_map's, the image's texels' x its
 *              material numbers (lower_texture.c); its map, the textures at
 *              0, 1, 2...
 *   density_file: params[0].x the voxels' dev_image (four voxels a texel,
 *              src/eval_df3.c), yzw the sizes nx, ny, nz; params[1].x the
 *              interpolation (0 nearest, 1 trilinear, 2 tricubic)
 *   function:  params[0].x the scene's function (scene.functions)
 *   slope:     params[0].xyz the slope's unit direction, params[1].xyz the
 *              altitude's, each times its share of their summed lengths;
 *              params[0].w, params[1].w the slope's range, low and width
 *   mandel, julia, magnet: params[0].x the iteration limit, y the exponent
 *              (2-33; magnet: its type, 1 or 2, plus 2 in the julia form),
 *              zw the julia constant; params[1].x the interior type (0),
 *              y its factor (1), z the exterior type (1), w its factor (1)
 *   object:    params[0].x the int bits of the PRIM_CSG record (prims) of its
 *              object, which no BVH holds, or -1: inside nowhere
 *   granite, leopard, ...: none */
typedef struct {
	float4 rows[3];
	int kind, wave, noise_generator, flags;
	float frequency, phase, wave_exponent, bump_size;
	float4 params[2];
	int warp_first, warp_count;   /* dev_warp entries, applied in order */
	int map_first, map_count;     /* dev_map_entry entries, by increasing value */
	float4 normal;
} dev_pattern;
/* PATTERN_NO_BUMP_SCALE: POV-Ray's no_bump_scale: a normal's pattern
 * transformations scale its bumps (the normal is not made unit length before
 * and after them).
 * PATTERN_NORMAL_MAP: a normal's map entries are normals (normal_map, checker
 * normal { } normal { }, average): an entry's pigment is its normal's
 * dev_pattern, or -1 for none (texture_normal).
 * PATTERN_UV: uv_mapping: the point the rows map is the hit's <u, v, 0>
 * (shape_uv), not its place in space.
 * PATTERN_IN_PARENT: a pigment map's entry whose parent has warps that no
 * matrix holds (turbulence, repeat, black_hole...): the point its rows map is
 * the parent's point after all the parent's warps, as POV-Ray's
 * Compute_Pigment hands an entry its TPoint, not the point in space. */
enum { PATTERN_NO_BUMP_SCALE = 1, PATTERN_NORMAL_MAP = 2, PATTERN_UV = 4, PATTERN_IN_PARENT = 8 };

/* An entry of a pattern's map, 32 bytes: a colour, or a nested pigment (a
 * pigment_map, or checker pigment { } pigment { }) when pigment >= 0; in a
 * pattern of whole textures, a texture: its dev_material (material). */
typedef struct {
	float4 colour;   /* rgb; w: filter */
	float transmit, value;
	int pigment, material;
} dev_map_entry;

/* An image of an image_map, 16 bytes: its texels are texels[first ..
 * first + width * height - 1], top row first, rgb in the scene's working
 * gamma (POV-Ray's file gamma rules applied on the host, lower_texture.c) and
 * w the alpha; IMAGE_PREMULTIPLIED: rgb is multiplied by alpha (OpenEXR's),
 * and lookups unmultiply after interpolating, as POV-Ray does. However many
 * pigments use a file, it is there once. */
typedef struct {
	int width, height, first, flags;
} dev_image;
/* IMAGE_FILTER: a second plane of width * height texels follows the colours,
 * each texel's filter in x: a palette's filter N, V (POV-Ray's per entry). */
enum { IMAGE_PREMULTIPLIED = 1, IMAGE_FILTER = 2 };

/* The objects buffer: one int of POV-Ray's object flags per scene object (the
 * values of scene.h's OBJ_ flags), indexed by dev_prim.object. */
enum {
	OBJECT_NO_SHADOW = 1, OBJECT_NO_IMAGE = 2, OBJECT_NO_REFLECTION = 4, OBJECT_HOLLOW = 8,
	OBJECT_DOUBLE_ILLUMINATE = 16,
};

/* A fog { }, 80 bytes: POV-Ray 3.7's fog (kernels/fog.cl). A ray that is not
 * inside a solid (non-hollow) object sees every fog over its whole length.
 * type: FOG_CONSTANT or FOG_GROUND (ground fog: density 1 below offset along
 *   up, 1 / (1 + h^2) at h = (height - offset) / alt above it).
 * turb_on: 1 when the fog is turbulent: the distance through it shrinks by
 *   turbulence at the segment's middle (turb.xyz scales the point), turb.w
 *   turb_depth, with omega, lambda and octaves. */
enum { FOG_CONSTANT = 1, FOG_GROUND = 2 };
typedef struct {
	float4 colour;      /* rgb; w: filter */
	float4 up;          /* xyz: unit up (ground fog); w: transmit, the least transmittance */
	float4 turb;        /* xyz: turbulence; w: turb_depth */
	float distance, offset, alt, omega;
	float lambda;
	int octaves, type, turb_on;
} dev_fog;

/* A rainbow { }, 80 bytes: POV-Ray 3.7's rainbow (kernels/rainbow.cl), as
 * Parse_Rainbow leaves it. Angles in radians: angle the band's inner edge,
 * width its width; arc_angle and falloff_angle half those written, so a
 * ray's angle from up in the plane square to direction is against them.
 * pattern: the colour_map as a gradient x pigment's dev_pattern, read at
 * the band's index. */
typedef struct {
	float4 direction;   /* xyz: unit antisolar vector; w: angle */
	float4 up;          /* xyz: unit up, square to direction; w: width */
	float4 right;       /* xyz: up x direction; w: distance */
	float jitter, arc_angle, falloff_angle, falloff_width;
	int pattern;
	int pad[3];
} dev_rainbow;

/* A media { }, 128 bytes: POV-Ray 3.7's participating media (kernels/media.cl).
 * Coefficients are per unit of length, times the density at the point: the
 * product of the colours of densities (each a dev_material whose pigment is
 * the density { }, placed as the interior, -1: none) and density_rgb.
 * Extinction is absorption + scattering * scattering.w (POV-Ray's extinction).
 * type: MEDIA_ISOTROPIC ... MEDIA_HG, POV-Ray's scattering types 1 to 5.
 * Sampling (the Whitted integrator): method 1, 2 or 3, intervals, samples, and
 * for method 3 aa_level, sampling.y aa_threshold and sampling.x jitter. */
enum { MEDIA_ISOTROPIC = 1, MEDIA_MIE_HAZY, MEDIA_MIE_MURKY, MEDIA_RAYLEIGH, MEDIA_HG };
#define MEDIA_DENSITIES 4
typedef struct {
	float4 absorption;   /* rgb; w: Henyey-Greenstein's eccentricity */
	float4 emission;     /* rgb; w: the largest density (the path tracer's majorant is
	                      * w * the largest channel of absorption + scattering) */
	float4 scattering;   /* rgb; w: scattering's share of the extinction */
	float4 density_rgb;  /* rgb: the constant densities' product; w: 1 */
	float4 sampling;     /* x: jitter, y: aa_threshold, z: ratio, w: see chi_1 */
	int method, intervals, min_samples, max_samples;
	int aa_level, type;
	float chi_1, chi_z;  /* methods 1 and 2's extra samples (kernels/media_whitted.cl): the
	                      * chi-square quantile at confidence for 1 degree of freedom, and
	                      * the normal one Wilson and Hilferty's approximation takes for more;
	                      * sampling.w: variance over the quantile at max_samples - 1 */
	int density[MEDIA_DENSITIES];
} dev_media;

/* A light_source, 128 bytes. POV-Ray's lights are invisible and do not fall off
 * with distance unless fade_power is given; every vertex samples all of them. */
enum { LIGHT_KIND_POINT = 0, LIGHT_KIND_SPOT = 1, LIGHT_KIND_PARALLEL = 2 };
typedef struct {
	float4 position;    /* w: fade_distance (0: no fade) */
	float4 color;       /* w: fade_power */
	float4 axis1;       /* area light: the rectangle's first side; w: 1 for an area light */
	float4 axis2;       /* area light: the second side; w: 1 for a circular area light */
	float4 spot;        /* xyz: unit direction the light points to; w: cos(radius) */
	float cos_falloff, tightness;
	int kind, shadowless;
	float4 grid;        /* area light as POV-Ray's grid: x, y: size1, size2 (0: not an
	                     * area light), z: adaptive level, w: 1 for orient */
	int media_attenuation;  /* 1: fogs dim its light on the way (fog_shadow) */
	int no_media_interaction;  /* 1: media do not scatter its light (POV-Ray's media_interaction off) */
	int pad[2];
} dev_light;

/* The sky's importance sampling (src/lower_sky.c, kernels/sky_sample.cl),
 * 112 bytes: a sky_sphere of one spherical image_map, whose texels' brightness
 * times their solid angle is a piecewise-constant density over the image's
 * directions. rows: the linear map from a world direction to the image's space
 * (the pattern's rows without their translation, which must be 0); inv: its
 * inverse. The sky_cdf buffer holds the rows' cdf (height + 1 floats, the
 * top row first, as in the image), then each row's cdf over its texels
 * (width + 1 floats each). det: |det rows|, for the Jacobian from the image's
 * directions to the world's. */
typedef struct {
	float4 rows[3];
	float4 inv[3];
	int width, height;
	float det;
	int pad;
} dev_sky;

/* An emissive primitive (of a shape in PRIM_EMITTERS), chosen for next-event
 * estimation with probability proportional to its power. 16 bytes. */
typedef struct {
	float cdf;          /* the probabilities of the emitters up to and with this one */
	float pdf;          /* the probability of choosing this one */
	float area;
	int prim;
} dev_emitter;

/* POV-Ray's camera types (dev_params.lens.z; kernels/camera.cl makes their rays). */
enum {
	CAMERA_PERSPECTIVE = 0, CAMERA_ORTHOGRAPHIC, CAMERA_FISHEYE, CAMERA_ULTRA_WIDE_ANGLE, CAMERA_OMNIMAX,
	CAMERA_PANORAMIC, CAMERA_CYLINDER_1, CAMERA_CYLINDER_2, CAMERA_CYLINDER_3, CAMERA_CYLINDER_4,
	CAMERA_SPHERICAL, CAMERA_MESH, CAMERA_TYPES
};

enum { INTEGRATOR_PATH = 0, INTEGRATOR_NAIVE = 1, INTEGRATOR_WHITTED = 2 };

/* Ray kinds, and counters added up per pass by the kernel: rays of each kind, and
 * the BVH node tests and primitive tests they made. */
enum { RAY_CAMERA, RAY_BOUNCE, RAY_SHADOW, RAY_KINDS };
enum {
	COUNT_RAYS = 0,                    /* + kind */
	COUNT_NODES = RAY_KINDS,           /* + kind */
	COUNT_PRIMS = 2 * RAY_KINDS,       /* + kind */
	COUNT_N = 3 * RAY_KINDS,
};

/* Everything a render pass needs besides the buffers, 192 bytes. The camera
 * vectors are POV-Ray's after look_at: a perspective ray is direction + sx * right +
 * sy * up with sx, sy in [-0.5, 0.5], sy upwards. cam_right.w is the camera's
 * angle (the spherical camera's horizontal one), cam_up.w the spherical camera's
 * vertical angle, both in radians. */
typedef struct {
	float4 cam_location, cam_direction, cam_right, cam_up;
	float4 background;  /* rgb: what rays that leave the scene see; w: under +UA, how much
	                     * of it is transparent, 0 without */
	float4 lens;        /* x: aperture (0: pinhole), y: POV-Ray's focal distance,
	                     * z: the camera's type, CAMERA_ */
	int width, height, max_depth, seed;
	int n_lights, sample_base, samples_per_pass, n_prims;
	int n_planes, n_emitters, integrator, aov;   /* aov: 1 when the aov buffer is there */
	float4 classic;     /* the Whitted integrator's: w: adc_bailout; x (both integrators'):
	                     * under +UA, the background's filter + transmit, 0 without */
	int scene_flags;    /* SCENE_ */
	int sky;            /* the sky_sphere's first material, or -1: the background alone */
	int sky_layers;     /* its pigments are materials sky .. sky + sky_layers - 1 */
	int n_fogs;         /* dev_fog records */
	int camera_solids;  /* the solid (non-hollow) objects around the camera: POV-Ray fogs no
	                     * camera ray inside one */
	int atmosphere, n_atmosphere;  /* the scene-level media's dev_media records */
	int sky_sampled;    /* 1: the path tracer samples the sky by sky_dist (kernels/sky_sample.cl) */
	int camera_normal;  /* the camera's normal { }: the pattern (dev_pattern) that perturbs every
	                     * camera ray's direction (kernels/texture.cl, camera_perturb), or -1 */
	int n_rainbows;     /* dev_rainbow records */
	int pad_params[2];
} dev_params;
/* SCENE_SHADOWS_PASS: some surface lets shadow rays through (no_shadow, filter,
 * transmit), so shadow rays look at what they meet instead of stopping at the first.
 * SCENE_SKY_LEGACY: the sky_sphere blends its layers as POV-Ray before 3.7 (a
 * scene whose #version is older).
 * SCENE_MEDIA: some interior has media, so shadow rays follow the interiors they cross.
 * SCENE_UV: some pattern is uv_mapped, so shading points find their uv. */
enum { SCENE_SHADOWS_PASS = 1, SCENE_SKY_LEGACY = 2, SCENE_MEDIA = 4, SCENE_UV = 8 };

/* The scene's buffers, read by every kernel that renders, in the kernels'
 * argument order (after them: params, film, counters, aov). One list for the
 * host's buffers (render.c) and the kernels' parameters and scene_data
 * (kernels/scene.cl): type and name. */
#define SCENE_BUFFERS(X) \
	X(bvh_node, nodes) \
	X(dev_prim, prims) \
	X(float4, normals) \
	X(dev_material, materials) \
	X(dev_light, lights) \
	X(dev_emitter, emitters) \
	X(int, objects) \
	X(dev_pattern, patterns) \
	X(dev_warp, warps) \
	X(dev_map_entry, maps) \
	X(dev_image, images) \
	X(float4, texels) \
	X(dev_fog, fogs) \
	X(dev_rainbow, rainbows) \
	X(float4, camera_rays) \
	X(dev_media, media) \
	X(dev_sky, sky_dist) \
	X(float, sky_cdf)

/* The aov buffer, when asked for: three float4 a pixel, sums over its samples.
 * [0] rgb: albedo of the first surface; w: samples that hit a surface
 * [1] xyz: its shading normal, facing the camera
 * [2] x: its distance from the camera; y: the object number of sample 0's hit, -1 for none */
#define AOV_FLOAT4S 3

/* The film buffer: a long4 a pixel, the sums of its samples' rgb in fixed point
 * with this many fraction bits, and w the camera ray's tests (kernels/film.cl). */
#define FILM_FRACTION_BITS 28

#endif
