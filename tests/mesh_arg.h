/* mesh_arg.h: the FILE=N arguments with which the tests scripts hand the C tests
 * their meshes (issue 13: the scripts choose the meshes, which may be the
 * generated one, assimp's test models or the optional larger ones). */
#ifndef ECLAT_TESTS_MESH_ARG_H
#define ECLAT_TESTS_MESH_ARG_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Splits arg, "FILE=N", into path (size bytes) and *n (N > 0). Returns 0, or -1
 * with a message when arg is not of that form. */
static inline int mesh_arg(const char *arg, char *path, size_t size, int *n)
{
	const char *eq = strrchr(arg, '=');
	char *end;
	long v = eq ? strtol(eq + 1, &end, 10) : 0;
	if (!eq || eq == arg || (size_t)(eq - arg) >= size || end == eq + 1 || *end || v <= 0 || v > 1000000000) {
		fprintf(stderr, "'%s' is not FILE=N (a positive count)\n", arg);
		return -1;
	}
	snprintf(path, size, "%.*s", (int)(eq - arg), arg);
	*n = (int)v;
	return 0;
}

#endif
