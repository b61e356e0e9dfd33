/* mesh_io.h: triangle meshes from files (OBJ, PLY, STL, OFF, glTF and every other
 * format assimp reads) into a scene_mesh. */
#ifndef ECLAT_MESH_IO_H
#define ECLAT_MESH_IO_H

#include <stddef.h>
#include <stdio.h>

#include "scene.h"

/* Seconds assimp may take on one file before eclat gives up on it
 * (--mesh-time-limit): some corrupt files make it loop for ever. */
#define MESH_IO_DEFAULT_TIME_LIMIT 120

/* Loads every triangle of the file, with the node transforms applied and shared
 * vertices joined; the file's own normals become shading normals when it has them
 * for every vertex. Points and lines are dropped. assimp gets time_limit seconds
 * (0: no limit), in a child process. Returns 0, or -1 with assimp's reason (or ours) in err. m's
 * arrays are the caller's (scene_add_mesh takes them). */
int mesh_io_load(const char *path, unsigned time_limit, double max_bytes, scene_mesh *m, char *err, size_t errlen);
/* What a mesh of n_v vertices (with normals or not) and n_faces triangles takes
 * once it is a scene's, its lowering included: max_bytes above bounds it (0: no
 * bound), checked with the counts before anything is allocated for the arrays. */
double mesh_io_bytes(double n_v, double n_faces, int normals);
/* 0 when such a mesh fits in max_bytes (0: no bound); else -1 with the numbers in err. */
int mesh_io_fits(double n_v, double n_faces, int normals, double max_bytes, char *err, size_t errlen);

/* Mesh files kept between the frames of an animation (mesh_io_cache.c):
 * mesh_io_load_cached is mesh_io_load, or a copy of what the same file (same
 * path, inode, size and times) gave before; c NULL: mesh_io_load. sweep drops
 * the files not asked for since the last sweep. */
typedef struct mesh_io_cache mesh_io_cache;
mesh_io_cache *mesh_io_cache_new(void);   /* NULL when out of memory */
void mesh_io_cache_free(mesh_io_cache *c);
int mesh_io_load_cached(mesh_io_cache *c, const char *path, unsigned time_limit, double max_bytes, scene_mesh *m,
                        char *err, size_t errlen);
void mesh_io_cache_sweep(mesh_io_cache *c);
int mesh_io_cache_hits(const mesh_io_cache *c);   /* files copied, not read, so far */

/* Writes m as POV-Ray's "#declare NAME = mesh2 { ... }" (vertex_vectors, the
 * normal_vectors when it has them, face_indices), which povray and eclat both
 * read; source names the file it came from in a comment. Returns -1 on a write error. */
int mesh_io_write_mesh2(const scene_mesh *m, const char *name, const char *source, FILE *out);

/* The same, in this process (mesh_io_load runs it in a child process, so that
 * assimp crashing on a corrupt file is an error, not the end of eclat). */
int mesh_io_load_here(const char *path, scene_mesh *m, char *err, size_t errlen);

#endif
