/* loader.h: a library that reads a file the scene names (an image, a font) runs
 * in a forked child with an alarm clock, as assimp does in src/mesh_io.c, so that
 * a crash or a hang on a hostile file is an error that names the file, never the
 * end of eclat. */
#ifndef ECLAT_LOADER_H
#define ECLAT_LOADER_H

#include <stddef.h>

/* In the child: reads what arg says and writes the answer to fd. Returns 0 when
 * all of it was written. */
typedef int (*loader_work)(int fd, void *arg);
/* In the parent: reads the answer from fd into arg. Returns 0; -1 when the
 * answer is an error (its message put in err); -2 when the answer stopped short
 * (the child died or gave up). */
typedef int (*loader_take)(int fd, void *arg, char *err, size_t errlen);

/* Runs work in a child, limited to time_limit seconds (0: none), and take here.
 * 0, or -1 with the reason in err: the answer's error, or what became of the
 * child, naming library ("FreeType", "OpenImageIO"). */
int loader_run(const char *library, unsigned time_limit, loader_work work, loader_take take, void *arg,
               char *err, size_t errlen);

/* Called before every fork of a loader child (here, and in src/mesh_io.c)
 * with the library the child runs, when set: src/image_module.c sets it, so
 * that a load of its module under way on another thread ends before a fork
 * (a child would inherit it half made), and that OpenImageIO's children find
 * the module loaded. */
extern void (*loader_before_fork)(const char *library);

/* A work that fails writes its message as LOADER_ERR_LEN bytes after its own
 * header, which says it failed; the take reads it with loader_take_error, which
 * returns -1 with the message in err, or -2 when the answer stopped short. */
#define LOADER_ERR_LEN 512
int loader_take_error(int fd, char *err, size_t errlen);

/* All of n bytes, through EINTR and short transfers: 0, or -1. */
int loader_write(int fd, const void *p, size_t n);
int loader_read(int fd, void *p, size_t n);

/* What a regular file is not: "a folder", "an empty file", or NULL when path is
 * a file with something in it (or cannot be looked at: opening it says why). */
const char *loader_not_a_file(const char *path);

#endif
