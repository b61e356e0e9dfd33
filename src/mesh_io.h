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
 * (0: no limit). Returns 0, or -1 with assimp's reason (or ours) in err. m's
 * arrays are the caller's (scene_add_mesh takes them). */
int mesh_io_load(const char *path, unsigned time_limit, scene_mesh *m, char *err, size_t errlen);

/* Writes m as POV-Ray's "#declare NAME = mesh2 { ... }" (vertex_vectors, the
 * normal_vectors when it has them, face_indices), which povray and eclat both
 * read; source names the file it came from in a comment. Returns -1 on a write error. */
int mesh_io_write_mesh2(const scene_mesh *m, const char *name, const char *source, FILE *out);

/* The same, in this process (mesh_io_load runs it in a child process, so that
 * assimp crashing on a corrupt file is an error, not the end of eclat). */
int mesh_io_load_here(const char *path, scene_mesh *m, char *err, size_t errlen);

#endif
