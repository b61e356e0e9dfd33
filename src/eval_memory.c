/* eval_memory.c: the memory a scene's images, meshes and height fields take,
 * claimed before each is allocated, against --memory-limit or, by default,
 * what the host had available when the scene started. A scene that would not
 * fit says so at the line that asked for too much, with the numbers, instead
 * of being killed by the kernel half-way. */
#include "eval_int.h"
#include "host_memory.h"

static double limit(struct eval *e)
{
	if (e->memory_limit == 0)
		e->memory_limit = e->opt->memory_limit > 0 ? e->opt->memory_limit : host_memory_available();
	return e->memory_limit;
}

double eval_memory_left(struct eval *e)
{
	double l = limit(e);
	if (l <= 0)
		return 1e30;   /* the host does not say: no limit */
	return l > e->memory_used ? l - e->memory_used : 0;
}

int eval_memory_claim(struct eval *e, src_loc loc, double bytes, const char *what)
{
	if (bytes <= eval_memory_left(e)) {
		e->memory_used += bytes;
		return 0;
	}
	char need[32], used[32], lim[32];
	host_memory_format(bytes, need, sizeof need);
	host_memory_format(e->memory_used, used, sizeof used);
	host_memory_format(limit(e), lim, sizeof lim);
	const char *by = e->opt->memory_limit > 0 ? "--memory-limit allows" : "this host has available (--memory-limit)";
	if (e->memory_used > 0)
		eval_error(e, loc, "%s needs %s, and the scene's images and meshes take %s already: more than the %s %s",
		           what, need, used, lim, by);
	else
		eval_error(e, loc, "%s needs %s, more than the %s %s", what, need, lim, by);
	return -1;
}
