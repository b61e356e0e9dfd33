/* eval.h: evaluates a syntax tree (directives, expressions, #include) into a scene. */
#ifndef ECLAT_EVAL_H
#define ECLAT_EVAL_H

#include "ast.h"
#include "scene.h"

/* Fills s (already scene_init'ed) from the file's tree. Returns 0, or -1 after
 * printing the errors; the scene is then incomplete and must only be freed. */
int eval_scene(const ast_node *root, scene *s);

#endif
