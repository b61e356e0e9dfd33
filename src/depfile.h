/* depfile.h: --depfile FILE, a make rule naming every file a render read
 * (the scene, its #include files, mesh files, images, fonts, #fopen'd files)
 * as prerequisites of the images it wrote, and each of them as a target of
 * its own with no recipe (gcc's -MP), so that make neither misses a changed
 * include nor stops when one is deleted:
 *
 *   depfile *d = depfile_new();
 *   depfile_add(d, DEPFILE_INPUT, "scene.pov");  ... and what the evaluator reads
 *   depfile_add(d, DEPFILE_TARGET, "scene.png");
 *   depfile_write(d, "scene.d");
 *   depfile_free(d); */
#ifndef ECLAT_DEPFILE_H
#define ECLAT_DEPFILE_H

typedef struct depfile depfile;
enum { DEPFILE_TARGET, DEPFILE_INPUT };

depfile *depfile_new(void);   /* NULL when out of memory */
/* Adds a path once (a second add of it does nothing). Returns -1 when out of memory. */
int depfile_add(depfile *d, int kind, const char *path);
/* For eval_options.on_read: ctx is the depfile. */
void depfile_on_read(void *ctx, const char *path);
/* Writes the rule to path (atomically: a temporary file renamed). Returns 0,
 * or -1 after printing why. */
int depfile_write(const depfile *d, const char *path);
void depfile_free(depfile *d);

#endif
