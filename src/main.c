/* main.c: eclat's command line: parse, evaluate, lower, render, write. */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <signal.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli_pov.h"
#include "depfile.h"
#include "device.h"
#include "device_points.h"
#include "eval.h"
#include "film.h"
#include "host_memory.h"
#include "image_table.h"
#include "lower.h"
#include "merge.h"
#include "mesh_io.h"
#include "parse.h"
#include "preview.h"
#include "render.h"
#include "split_plan.h"
#include "render_keep.h"
#include "suggest.h"

#define DEFAULT_WIDTH 640
#define DEFAULT_HEIGHT 480
#define DEFAULT_SAMPLES 64
#define DEFAULT_MAX_DEPTH 5
#define MAX_SIZE 32768
/* The paper does not state its maximum depth; 9 reproduces its measured ~108
 * tests per camera ray on a 60,000-triangle statue (the bunny gives 105 here). */
#define DEFAULT_MEDIAN_DEPTH 9
#define MAX_AOVS 8
#define MAX_LIST 64   /* -I and -D options each */

struct options {
	const char *scene, *output, *kernel_dir, *export_mesh2, *depfile;
	int width, height, samples, seed, max_depth, device, quiet, integrator;
	int list_devices, check, dump_ast, dump_scene;
	double time_limit, checkpoint;
	int bvh, median_depth, bvh_layout, stats, skip_unsupported;
	const char *include_dirs[MAX_LIST], *declares[MAX_LIST];
	int n_include_dirs, n_declares;
	int io_security;
	const char *io_read_dirs[MAX_LIST], *io_write_dirs[MAX_LIST];
	int n_io_read_dirs, n_io_write_dirs;
	const char *aov_name[MAX_AOVS], *aov_file[MAX_AOVS];
	int n_aovs;
	int max_include_depth, max_macro_depth;   /* 0: the evaluator's defaults */
	long max_loop_iterations;
	int mesh_time_limit;
	double memory_limit;   /* bytes; 0: what the host has */
	int threads;      /* --threads, POV-Ray's +WT; 0: the device's own */
	int range_first, range_count;   /* --sample-range; count 0: all samples */
	int devices[MAX_LIST], n_devices;   /* --device 0,2 (more than one); --device all: n_devices -1 */
	int preview, pause;   /* --preview (POV-Ray's +D), --pause (+P): the window, kept open at the end */
	const char *resume;             /* --resume FILE */
	int resume_output;              /* --continue, POV-Ray's +C: resume from the output when it is there */
	cli_pov pov;      /* what POV-Ray's switches and INI files asked for besides */
	int no_sky_sampling;   /* --sky-sampling off */
};

enum { OPT_SEED = 256, OPT_MAX_DEPTH, OPT_DEVICE, OPT_LIST_DEVICES, OPT_KERNEL_DIR,
       OPT_CHECK, OPT_DUMP_AST, OPT_DUMP_SCENE, OPT_INTEGRATOR, OPT_TIME_LIMIT, OPT_CHECKPOINT, OPT_AOV, OPT_BVH, OPT_BVH_LAYOUT, OPT_STATS, OPT_SKIP_UNSUPPORTED, OPT_EXPORT_MESH2,
       OPT_MAX_INCLUDE_DEPTH, OPT_MAX_MACRO_DEPTH, OPT_MAX_LOOP_ITERATIONS, OPT_MESH_TIME_LIMIT,
       OPT_IO_SECURITY, OPT_IO_ALLOW, OPT_IO_ALLOW_WRITE, OPT_THREADS, OPT_SAMPLE_RANGE, OPT_RESUME,
       OPT_CONTINUE, OPT_MEMORY_LIMIT, OPT_DEPFILE, OPT_SKY_SAMPLING, OPT_PREVIEW, OPT_NO_PREVIEW, OPT_PAUSE,
       OPT_NO_PAUSE };

static const struct option long_options[] = {
	{ "output", required_argument, NULL, 'o' },
	{ "width", required_argument, NULL, 'W' },
	{ "height", required_argument, NULL, 'H' },
	{ "samples", required_argument, NULL, 's' },
	{ "seed", required_argument, NULL, OPT_SEED },
	{ "max-depth", required_argument, NULL, OPT_MAX_DEPTH },
	{ "integrator", required_argument, NULL, OPT_INTEGRATOR },
	{ "sky-sampling", required_argument, NULL, OPT_SKY_SAMPLING },
	{ "time-limit", required_argument, NULL, OPT_TIME_LIMIT },
	{ "checkpoint", required_argument, NULL, OPT_CHECKPOINT },
	{ "sample-range", required_argument, NULL, OPT_SAMPLE_RANGE },
	{ "resume", required_argument, NULL, OPT_RESUME },
	{ "continue", no_argument, NULL, OPT_CONTINUE },
	{ "aov", required_argument, NULL, OPT_AOV },
	{ "bvh", required_argument, NULL, OPT_BVH },
	{ "bvh-layout", required_argument, NULL, OPT_BVH_LAYOUT },
	{ "stats", no_argument, NULL, OPT_STATS },
	{ "include-path", required_argument, NULL, 'I' },
	{ "declare", required_argument, NULL, 'D' },
	{ "skip-unsupported", no_argument, NULL, OPT_SKIP_UNSUPPORTED },
	{ "export-mesh2", required_argument, NULL, OPT_EXPORT_MESH2 },
	{ "max-include-depth", required_argument, NULL, OPT_MAX_INCLUDE_DEPTH },
	{ "max-macro-depth", required_argument, NULL, OPT_MAX_MACRO_DEPTH },
	{ "max-loop-iterations", required_argument, NULL, OPT_MAX_LOOP_ITERATIONS },
	{ "mesh-time-limit", required_argument, NULL, OPT_MESH_TIME_LIMIT },
	{ "load-time-limit", required_argument, NULL, OPT_MESH_TIME_LIMIT },
	{ "memory-limit", required_argument, NULL, OPT_MEMORY_LIMIT },
	{ "io-security", required_argument, NULL, OPT_IO_SECURITY },
	{ "io-allow", required_argument, NULL, OPT_IO_ALLOW },
	{ "io-allow-write", required_argument, NULL, OPT_IO_ALLOW_WRITE },
	{ "threads", required_argument, NULL, OPT_THREADS },
	{ "depfile", required_argument, NULL, OPT_DEPFILE },
	{ "preview", no_argument, NULL, OPT_PREVIEW },
	{ "no-preview", no_argument, NULL, OPT_NO_PREVIEW },
	{ "pause", no_argument, NULL, OPT_PAUSE },
	{ "no-pause", no_argument, NULL, OPT_NO_PAUSE },
	{ "device", required_argument, NULL, OPT_DEVICE },
	{ "list-devices", no_argument, NULL, OPT_LIST_DEVICES },
	{ "kernel-dir", required_argument, NULL, OPT_KERNEL_DIR },
	{ "check", no_argument, NULL, OPT_CHECK },
	{ "dump-ast", no_argument, NULL, OPT_DUMP_AST },
	{ "dump-scene", no_argument, NULL, OPT_DUMP_SCENE },
	{ "quiet", no_argument, NULL, 'q' },
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, 'V' },
	{ NULL, 0, NULL, 0 },
};

static void usage(FILE *out)
{
	fprintf(out,
		"Usage: eclat [OPTIONS] SCENE.scn\n"
		"Render a POV-Ray-style scene with a path tracer on an OpenCL device.\n"
		"\n"
		"  -o, --output FILE     image to write; the extension picks the format (.png, .exr,\n"
		"                        .hdr, .tif, .jpg, .tga, .bmp, .webp, .ppm); default: SCENE's\n"
		"                        name with .png\n"
		"  -W, --width N         image width in pixels (default %d)\n"
		"  -H, --height N        image height in pixels (default %d)\n"
		"  -s, --samples N       samples per pixel (default %d)\n"
		"      --seed N          random seed (default 0)\n"
		"      --max-depth N     bounces per path (default: max_trace_level, else %d)\n"
		"      --integrator NAME path (default): light sampling with MIS; naive: the\n"
		"                        reference paper's random walk, for comparison; whitted:\n"
		"                        POV-Ray's classic model, one ray a pixel (fast preview)\n"
		"      --sky-sampling on|off  on (default): the path tracer samples a sky_sphere's\n"
		"                        HDR image by importance; off: bounce rays alone find it\n"
		"      --time-limit S    stop after S seconds, or at the samples, whichever is first\n"
		"      --checkpoint S    write the image rendered so far every S seconds\n"
		"      --sample-range FIRST:COUNT  render only samples FIRST to FIRST+COUNT-1 of\n"
		"                        each pixel into an EXR for 'eclat merge' (see eclat(1))\n"
		"      --resume FILE     continue the render an EXR of eclat's holds (a checkpoint)\n"
		"      --continue        --resume the output when it is there (POV-Ray's +C)\n"
		"      --aov NAME=FILE   also write an AOV: albedo, normal, depth, id or heat\n"
		"                        (box and primitive tests per sample); repeatable\n"
		"      --bvh NAME        sah (default): binned SAH; median[:DEPTH]: the reference\n"
		"                        paper's split at the middle of the longest side, to a\n"
		"                        depth of 9 or DEPTH, for comparison\n"
		"      --bvh-layout NAME wide (default): 4-wide nodes with quantized boxes;\n"
		"                        binary: the builders' tree as it is, for comparison\n"
		"      --stats           print the BVHs' statistics and the tests per ray\n"
		"      --threads N       at most N threads on PoCL's CPU device (POV-Ray's +WT)\n"
		"      --device N        OpenCL device to use (default: first GPU, else first CPU);\n"
		"                        N,M,... or all: render on several at once\n"
		"      --list-devices    list the OpenCL devices and exit\n"
		"      --kernel-dir DIR  read the kernel sources from DIR instead of the built-in copy\n"
		"  -I, --include-path DIR  look for #include files in DIR too (repeatable)\n"
		"  -D, --declare NAME=VALUE  declare NAME before the scene is read, as #declare\n"
		"                        does; VALUE is a number, a \"string\" or an expression\n"
		"      --skip-unsupported  leave out objects eclat cannot render, with a warning\n"
		"      --export-mesh2 FILE  write the mesh file FILE (any format assimp reads) as a\n"
		"                        POV-Ray mesh2 include, to -o or standard output, and exit\n"
		"      --max-include-depth N  #include files nested at most N deep (default %d)\n"
		"      --max-macro-depth N  macro calls nested at most N deep (default %d, at most %d)\n"
		"      --max-loop-iterations N  stop a #while or #for after N turns (default %ld)\n"
		"      --load-time-limit S, --mesh-time-limit S  give up on a mesh, image or font\n"
		"                        file a library is still reading after S seconds\n"
		"                        (default %d; 0: no limit)\n"
		"      --memory-limit SIZE  the memory (512M, 4G) the scene's images, meshes and\n"
		"                        height fields may take (default: what the host has free)\n"
		"      --io-security LEVEL  the files a scene may read and write: restricted\n"
		"                        (default): its folder, the include folders, the current\n"
		"                        folder and those allowed; read-only: reads anywhere,\n"
		"                        writes restricted; none: anything (see SECURITY in eclat(1))\n"
		"      --io-allow DIR    let the scene read files in DIR and below (repeatable)\n"
		"      --io-allow-write DIR  let it read and write files in DIR and below (repeatable)\n"
		"      --depfile FILE    write a make rule: the images depend on the scene and every\n"
		"                        file it read (includes, meshes, images, fonts, #fopen)\n"
		"      --preview         show the image in a window as it renders (POV-Ray's +D);\n"
		"                        Escape, q or closing it stops the render as Ctrl-C does\n"
		"      --pause           keep the window open at the end until a key (POV-Ray's +P)\n"
		"      --no-preview, --no-pause  the defaults (POV-Ray's -D, -P)\n"
		"      --check           check the scene for errors and warnings, render nothing\n"
		"      --dump-ast        print the syntax tree and exit\n"
		"      --dump-scene      print the evaluated scene in world space and exit\n"
		"  -q, --quiet           print only errors and warnings\n"
		"  -h, --help            show this help and exit\n"
		"  -V, --version         show the version and exit\n"
		"\n"
		"POV-Ray's switches (+W320 +H240 +A -D +FN16 +Iscene.pov...), KEY=VALUE settings\n"
		"and INI files (render.ini, render.ini[Section]) work too: see FOR POV-RAY USERS in\n"
		"eclat(1). -D NAME=VALUE declares; -D alone is POV-Ray's display switch.\n"
		"Ctrl-C finishes the pass under way and writes the image rendered so far.\n"
		"'eclat merge PART.exr... -o IMAGE' merges the parts of a split render.\n"
		"The scene language is described in eclat-scene(5), the options in eclat(1).\n",
		DEFAULT_WIDTH, DEFAULT_HEIGHT, DEFAULT_SAMPLES, DEFAULT_MAX_DEPTH, EVAL_DEFAULT_INCLUDE_DEPTH,
		EVAL_DEFAULT_MACRO_DEPTH, EVAL_MAX_MACRO_DEPTH_LIMIT, EVAL_DEFAULT_LOOP_ITERATIONS,
		MESH_IO_DEFAULT_TIME_LIMIT);
}

/* A whole number in [lo, hi], or exit 1 naming the option. */
static int int_arg(const char *opt, const char *s, long lo, long hi)
{
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (errno || end == s || *end || v < lo || v > hi) {
		fprintf(stderr, "eclat: %s needs a whole number from %ld to %ld, not '%s'\n", opt, lo, hi, s);
		diag_exit(1);
	}
	return (int)v;
}

/* A number of seconds > 0, or exit 1 naming the option. */
static double seconds_arg(const char *opt, const char *s)
{
	char *end;
	errno = 0;
	double v = strtod(s, &end);
	if (errno || end == s || *end || !(v > 0) || v > 1e9) {
		fprintf(stderr, "eclat: %s needs a number of seconds greater than 0, not '%s'\n", opt, s);
		diag_exit(1);
	}
	return v;
}

/* --sample-range FIRST:COUNT */
static void range_arg(struct options *o, const char *s)
{
	char *end;
	errno = 0;
	long first = strtol(s, &end, 10), count = -1;
	if (!errno && end != s && *end == ':' && end[1])
		count = strtol(end + 1, &end, 10);
	if (errno || *end || first < 0 || count < 1 || first > (1 << 24) || count > (1 << 24)) {
		fprintf(stderr, "eclat: --sample-range needs FIRST:COUNT, a sample from 0 and a count from 1, not '%s'\n",
		        s);
		diag_exit(1);
	}
	o->range_first = (int)first;
	o->range_count = (int)count;
}

/* --device N | N,M... | all */
static void device_arg(struct options *o, const char *s)
{
	o->n_devices = 0;
	if (strcmp(s, "all") == 0) {
		o->n_devices = -1;
		return;
	}
	char *list = strdup(s), *save = NULL;
	for (char *t = list ? strtok_r(list, ",", &save) : NULL; t && o->n_devices < MAX_LIST;
	     t = strtok_r(NULL, ",", &save))
		o->devices[o->n_devices++] = int_arg("--device", t, 0, 63);
	free(list);
	if (o->n_devices == 0 || s[strlen(s) - 1] == ',') {
		fprintf(stderr, "eclat: --device needs a device number, a list of them (0,2) or all, not '%s'\n", s);
		diag_exit(1);
	}
	o->device = o->n_devices > 0 ? o->devices[0] : -1;
}

/* --bvh sah | median[:DEPTH] */
static void bvh_arg(struct options *o, const char *s)
{
	o->bvh = LOWER_BVH_SAH;
	if (strcmp(s, "sah") == 0)
		return;
	if (strncmp(s, "median", 6) == 0 && (s[6] == '\0' || s[6] == ':')) {
		o->bvh = LOWER_BVH_MEDIAN;
		if (s[6] == ':')
			o->median_depth = int_arg("--bvh median:DEPTH", s + 7, 1, BVH_STACK_SIZE);
		return;
	}
	fprintf(stderr, "eclat: --bvh is sah, median or median:DEPTH, not '%s'\n", s);
	diag_exit(1);
}

/* --bvh-layout binary | wide */
static int layout_arg(const char *s)
{
	if (strcmp(s, "binary") == 0)
		return LOWER_LAYOUT_BINARY;
	if (strcmp(s, "wide") == 0)
		return LOWER_LAYOUT_WIDE;
	fprintf(stderr, "eclat: --bvh-layout is binary or wide, not '%s'\n", s);
	diag_exit(1);
}

static void list_arg(const char *opt, const char **list, int *n, const char *value)
{
	if (*n == MAX_LIST) {
		fprintf(stderr, "eclat: at most %d %s options\n", MAX_LIST, opt);
		diag_exit(1);
	}
	list[(*n)++] = value;
}

/* --io-security none | read-only | restricted: POV-Ray's levels */
static int io_security_arg(const char *s)
{
	if (strcmp(s, "restricted") == 0)
		return EVAL_IO_RESTRICTED;
	if (strcmp(s, "read-only") == 0)
		return EVAL_IO_READ_ONLY;
	if (strcmp(s, "none") == 0)
		return EVAL_IO_NONE;
	fprintf(stderr, "eclat: --io-security is restricted, read-only or none, not '%s'\n", s);
	diag_exit(1);
}

/* --io-allow DIR: a folder that is not there is a typo, which would otherwise
 * show only as a refusal later. */
static void io_dir_arg(const char *opt, const char **list, int *n, const char *dir)
{
	struct stat st;
	int there = stat(dir, &st) == 0;
	if (!there || !S_ISDIR(st.st_mode)) {
		fprintf(stderr, "eclat: %s needs a folder, not '%s': %s\n", opt, dir,
		        there ? "not a folder" : strerror(errno));
		diag_exit(1);
	}
	list_arg(opt, list, n, dir);
}

/* --aov NAME=FILE */
static void aov_arg(struct options *o, char *s)
{
	char *eq = strchr(s, '=');
	if (eq)
		*eq = '\0';
	if (!eq || !eq[1] || !film_aov_known(s)) {
		fprintf(stderr, "eclat: --aov needs NAME=FILE with NAME albedo, normal, depth, id or heat, not '%s'\n", s);
		diag_exit(1);
	}
	if (o->n_aovs == MAX_AOVS) {
		fprintf(stderr, "eclat: at most %d --aov options\n", MAX_AOVS);
		diag_exit(1);
	}
	o->aov_name[o->n_aovs] = s;
	o->aov_file[o->n_aovs++] = eq + 1;
}

static int integrator_arg(const char *s)
{
	if (strcmp(s, "path") == 0)
		return INTEGRATOR_PATH;
	if (strcmp(s, "naive") == 0)
		return INTEGRATOR_NAIVE;
	if (strcmp(s, "whitted") == 0)
		return INTEGRATOR_WHITTED;
	fprintf(stderr, "eclat: --integrator is path, naive or whitted, not '%s'\n", s);
	diag_exit(1);
}

static int sky_sampling_arg(const char *s)
{
	if (strcmp(s, "on") == 0 || strcmp(s, "off") == 0)
		return strcmp(s, "off") == 0;
	fprintf(stderr, "eclat: --sky-sampling is on or off, not '%s'\n", s);
	diag_exit(1);
}

/* After getopt_long's "unrecognized option '--widht'": the option meant. */
static void hint_option(const char *arg)
{
	if (strncmp(arg, "--", 2) != 0)
		return;
	char word[64];
	snprintf(word, sizeof word, "%.*s", (int)strcspn(arg + 2, "="), arg + 2);
	const char *near = NULL;
	int dist = 0;
	for (const struct option *l = long_options; l->name; l++)
		suggest_consider(word, l->name, &near, &dist);
	if (near)
		fprintf(stderr, "eclat: did you mean '--%s'?\n", near);
}

static void parse_options(int argc, char **argv, struct options *o)
{
	*o = (struct options){ .width = DEFAULT_WIDTH, .height = DEFAULT_HEIGHT,
	                       .median_depth = DEFAULT_MEDIAN_DEPTH, .bvh_layout = LOWER_LAYOUT_DEFAULT,
	                       .samples = DEFAULT_SAMPLES, .max_depth = -1, .device = -1,
	                       .mesh_time_limit = MESH_IO_DEFAULT_TIME_LIMIT };
	o->kernel_dir = getenv("ECLAT_KERNEL_DIR");
	static const char shortopts[] = "o:W:H:s:I:D:qhV";
	argc = cli_pov_args(argc, argv, long_options, shortopts, &o->pov, &argv);
	int c;
	while ((c = getopt_long(argc, argv, shortopts, long_options, NULL)) != -1) {
		switch (c) {
		case 'o': o->output = optarg; break;
		case 'W': o->width = int_arg("--width", optarg, 1, MAX_SIZE); break;
		case 'H': o->height = int_arg("--height", optarg, 1, MAX_SIZE); break;
		case 's': o->samples = int_arg("--samples", optarg, 1, 1 << 24); break;
		case OPT_SEED: o->seed = int_arg("--seed", optarg, 0, INT_MAX); break;
		case OPT_MAX_DEPTH: o->max_depth = int_arg("--max-depth", optarg, 0, 256); break;
		case OPT_DEVICE: device_arg(o, optarg); break;
		case OPT_THREADS: o->threads = int_arg("--threads", optarg, 1, 512); break;
		case OPT_DEPFILE: o->depfile = optarg; break;
		case OPT_PREVIEW: case OPT_NO_PREVIEW: o->preview = c == OPT_PREVIEW; break;
		case OPT_PAUSE: case OPT_NO_PAUSE: o->pause = c == OPT_PAUSE; break;
		case OPT_INTEGRATOR: o->integrator = integrator_arg(optarg); break;
		case OPT_SKY_SAMPLING: o->no_sky_sampling = sky_sampling_arg(optarg); break;
		case OPT_TIME_LIMIT: o->time_limit = seconds_arg("--time-limit", optarg); break;
		case OPT_CHECKPOINT: o->checkpoint = seconds_arg("--checkpoint", optarg); break;
		case OPT_SAMPLE_RANGE: range_arg(o, optarg); break;
		case OPT_RESUME: o->resume = optarg; break;
		case OPT_CONTINUE: o->resume_output = 1; break;
		case OPT_AOV: aov_arg(o, optarg); break;
		case OPT_BVH: bvh_arg(o, optarg); break;
		case OPT_BVH_LAYOUT: o->bvh_layout = layout_arg(optarg); break;
		case OPT_STATS: o->stats = 1; break;
		case 'I': list_arg("-I", o->include_dirs, &o->n_include_dirs, optarg); break;
		case 'D': list_arg("-D", o->declares, &o->n_declares, optarg); break;
		case OPT_SKIP_UNSUPPORTED: o->skip_unsupported = 1; break;
		case OPT_EXPORT_MESH2: o->export_mesh2 = optarg; break;
		case OPT_MAX_INCLUDE_DEPTH: o->max_include_depth = int_arg("--max-include-depth", optarg, 1, 1000); break;
		case OPT_MAX_MACRO_DEPTH:
			o->max_macro_depth = int_arg("--max-macro-depth", optarg, 1, EVAL_MAX_MACRO_DEPTH_LIMIT);
			break;
		case OPT_MAX_LOOP_ITERATIONS:
			o->max_loop_iterations = int_arg("--max-loop-iterations", optarg, 1, INT_MAX);
			break;
		case OPT_MESH_TIME_LIMIT:
			o->mesh_time_limit = int_arg("--mesh-time-limit", optarg, 0, 86400);
			break;
		case OPT_MEMORY_LIMIT:
			if (host_memory_parse(optarg, &o->memory_limit)) {
				fprintf(stderr, "eclat: --memory-limit needs a size such as 512M or 4G, not '%s'\n", optarg);
				diag_exit(1);
			}
			break;
		case OPT_IO_SECURITY: o->io_security = io_security_arg(optarg); break;
		case OPT_IO_ALLOW: io_dir_arg("--io-allow", o->io_read_dirs, &o->n_io_read_dirs, optarg); break;
		case OPT_IO_ALLOW_WRITE:
			io_dir_arg("--io-allow-write", o->io_write_dirs, &o->n_io_write_dirs, optarg);
			break;
		case OPT_LIST_DEVICES: o->list_devices = 1; break;
		case OPT_KERNEL_DIR: o->kernel_dir = optarg; break;
		case OPT_CHECK: o->check = 1; break;
		case OPT_DUMP_AST: o->dump_ast = 1; break;
		case OPT_DUMP_SCENE: o->dump_scene = 1; o->check = 1; break;
		case 'q': o->quiet = 1; break;
		case 'h': usage(stdout); diag_exit(0);
		case 'V': printf("eclat %s\n", PACKAGE_VERSION); diag_exit(0);
		default:
			hint_option(argv[optind - 1]);
			fprintf(stderr, "Try 'eclat --help' for more information.\n");
			diag_exit(1);
		}
	}
	o->scene = o->pov.scene;
	if (o->list_devices || (o->export_mesh2 && !o->scene))
		return;
	if (!o->scene || o->pov.n_plain_scenes > 1) {
		fprintf(stderr, !o->scene ? "eclat: no scene file given\n" : "eclat: give one scene file, not %d\n",
		        o->pov.n_plain_scenes);
		if (o->pov.after_display && o->scene)
			fprintf(stderr, "eclat: note: -D before '%s' is POV-Ray's display switch; "
			        "to declare, write -D NAME=VALUE\n", o->pov.after_display);
		fprintf(stderr, "Try 'eclat --help' for more information.\n");
		diag_exit(1);
	}
}

static int same_file(const char *a, const char *b)
{
	struct stat sa, sb;
	return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* Everything the user could get wrong about the output is checked before the
 * render, so no minutes of work are lost to a typo in a file name: here what
 * the file system says, before the scene is read; check_format after it. */
static int check_output(const char *scene, const char *output)
{
	if (strcmp(scene, output) == 0 || same_file(scene, output)) {
		fprintf(stderr, "eclat: refusing to write the image over the scene file '%s'\n", scene);
		return -1;
	}
	char *dir = strdup(output), *slash = dir ? strrchr(dir, '/') : NULL;
	if (slash)
		*slash = '\0';
	int writable = !dir || access(slash ? (slash == dir ? "/" : dir) : ".", W_OK) == 0;
	free(dir);
	if (!writable) {
		fprintf(stderr, "eclat: cannot write '%s': %s\n", output, strerror(errno));
		return -1;
	}
	return 0;
}

/* Whether OpenImageIO writes the output's format (with alpha, for +UA). Asked
 * once the scene is read and lowered, before the kernels are built: eclat's
 * image module loads meanwhile (src/image_module.c), and asking waits for it;
 * a file that cannot be written must not cost a kernel build first (1.6 s for
 * a small scene with PoCL's cache empty). */
static int check_format(const char *output, int alpha)
{
	const char *no_module = image_module_error();
	if (no_module) {
		fprintf(stderr, "eclat: cannot write '%s': %s\n", output, no_module);
		return -1;
	}
	if (alpha && image_format_known(output) && !image_format_alpha(output)) {
		fprintf(stderr, "eclat: cannot write '%s' with an alpha channel (+UA): the format has none "
		        "(use .png, .exr, .tif, .tga or .webp)\n", output);
		return -1;
	}
	if (!image_format_known(output)) {
		fprintf(stderr, "eclat: cannot write '%s': unknown image format (use .png, .exr, .hdr, .tif, .jpg, .tga, "
		        ".bmp, .webp or .ppm)\n", output);
		return -1;
	}
	return 0;
}

/* The signal that asked the render to stop, or 0: the pass under way finishes,
 * the image so far is written, and eclat exits 128 + the signal's number. */
static volatile sig_atomic_t stop_signal;

static void on_signal(int sig)
{
	stop_signal = sig;
}

/* The preview window (+D), open for all the frames; NULL: none. */
static preview *window;

/* The window's picture between passes: Escape, q or closing it stop the
 * render as Ctrl-C does. */
static int show_film(const film *f, void *ctx)
{
	if (!preview_show(ctx, f->rgb))
		return 0;
	stop_signal = SIGINT;
	return 1;
}

static void catch_signals(void)
{
	struct sigaction sa = { .sa_handler = on_signal, .sa_flags = SA_RESETHAND };
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);    /* a second Ctrl-C kills at once */
	sigaction(SIGTERM, &sa, NULL);
}

struct output {
	const char *path, *scene;
	int bits;          /* POV-Ray's +FN16: 16; 0: the format's own */
	const int *part;   /* POV-Ray's +SC +SR +EC +ER in pixels (CLI_REGION_), or NULL */
	split_info *info;  /* what an EXR records beside the film's sums, or NULL (another format, an AOV);
	                    * an EXR with alpha (+UA) holds no sums, and cannot be merged or resumed */
	int alpha;         /* POV-Ray's +UA: an alpha channel (transparent outside the part) */
};

/* POV-Ray's image of a part is the whole image, black outside the part. */
static const float *black_outside(const film *f, const int *part)
{
	float *rgb = malloc((size_t)f->width * f->height * 3 * sizeof *rgb);
	if (!rgb)
		return NULL;
	for (int y = 0; y < f->height; y++)
		for (int x = 0; x < f->width; x++) {
			size_t i = ((size_t)y * f->width + x) * 3;
			int in = x >= part[CLI_REGION_LEFT] && x <= part[CLI_REGION_RIGHT] && y >= part[CLI_REGION_TOP] &&
			         y <= part[CLI_REGION_BOTTOM];
			for (int c = 0; c < 3; c++)
				rgb[i + c] = in ? f->rgb[i + c] : 0.0f;
		}
	return rgb;
}

/* +UA: the film's alpha, 0 outside the part. */
static float *alpha_of(const film *f, const int *part)
{
	float *a = malloc((size_t)f->width * f->height * sizeof *a);
	if (!a || film_alpha(f, a)) {
		free(a);
		return NULL;
	}
	for (int y = 0; part && y < f->height; y++)
		for (int x = 0; x < f->width; x++)
			if (x < part[CLI_REGION_LEFT] || x > part[CLI_REGION_RIGHT] || y < part[CLI_REGION_TOP] ||
			    y > part[CLI_REGION_BOTTOM])
				a[(size_t)y * f->width + x] = 0.0f;
	return a;
}

static int write_film(const film *f, void *ctx)
{
	const struct output *out = ctx;
	float *alpha = out->alpha ? alpha_of(f, out->part) : NULL;
	image_meta meta = { out->scene, f->samples, out->bits, alpha };
	char err[512];
	const float *rgb = out->part ? black_outside(f, out->part) : f->rgb;
	int have = rgb && (alpha || !out->alpha);
	int rc = !have ? -1
	       : out->info && f->sums && !out->alpha ? split_write_film(f, rgb, out->info, out->path, err, sizeof err)
	       : image_write(out->path, rgb, f->width, f->height, &meta, err, sizeof err);
	if (rgb != f->rgb)
		free((float *)rgb);
	free(alpha);
	if (rc == 0)
		return 0;
	fprintf(stderr, "eclat: %s\n", have ? err : "out of memory");
	char kept[600];
	if (film_rescue(f, out->path, &meta, kept, sizeof kept) == 0)
		fprintf(stderr, "eclat: the %ld samples per pixel are kept in '%s'\n", f->samples, kept);
	return -1;
}

/* Writes the AOVs asked for into files (the frame's names); each is an image of
 * its own, linear in EXR. */
static int write_aovs(const struct options *o, char *const *files, const film *f)
{
	float *rgb = malloc((size_t)f->width * f->height * 3 * sizeof *rgb);
	int rc = rgb ? 0 : -1;
	for (int i = 0; rc == 0 && i < o->n_aovs; i++) {
		struct output out = { files[i], o->scene, 0, NULL, NULL, 0 };
		if (strcmp(o->aov_name[i], "heat") == 0) {
			image_meta meta = { o->scene, f->samples, 0, NULL };
			char err[512];
			double mean;
			rc = image_write_heat(out.path, f->heat, f->width, f->height, &meta, &mean, err, sizeof err);
			if (rc)
				fprintf(stderr, "eclat: %s\n", err);
			else if (!o->quiet)
				fprintf(stderr, "eclat: heat map: %.1f BVH tests per camera ray (per pixel per sample) on average\n", mean);
			continue;
		}
		film view = *f;
		view.rgb = rgb;
		rc = film_aov(f, o->aov_name[i], rgb) || write_film(&view, &out);
	}
	free(rgb);
	return rc;
}

static int needs_aov_buffer(const struct options *o)
{
	for (int i = 0; i < o->n_aovs; i++)
		if (strcmp(o->aov_name[i], "heat") != 0)
			return 1;
	return 0;
}

static void summary(const render_settings *rs, const render_stats *st, const device_ctx *d)
{
	double s = st->seconds > 0 ? st->seconds : 1e-9, m = 1e-6 / s;
	double paths = (double)rs->width * rs->height * st->samples;
	const uint64_t *c = st->counts + COUNT_RAYS;
	fprintf(stderr, "eclat: %dx%d, %ld samples in %.2f s on %s: %.2f M paths/s, %.2f M rays/s "
	        "(camera %.2f, bounce %.2f, shadow %.2f)\n", rs->width, rs->height, st->samples, s, d->name,
	        paths * m, render_rays(st) * m, c[RAY_CAMERA] * m, c[RAY_BOUNCE] * m, c[RAY_SHADOW] * m);
}

static int instances(const lower_result *lr)
{
	int n = 0;
	for (int i = 0; i < lr->n_prims; i++)
		n += lr->prims[i].type == PRIM_INSTANCE;
	return n;
}

/* --stats: each BVH as built, then what the rays cost. */
static void print_bvh_stats(const scene *s, const lower_result *lr)
{
	for (int i = 0; i < lr->n_stats; i++) {
		const lower_bvh_stats *b = &lr->stats[i];
		if (b->mesh < 0)
			fprintf(stderr, "bvh: top level (%d objects, %d of them placed meshes)", s->n_objects,
			        instances(lr));
		else
			fprintf(stderr, "bvh: mesh %d at %s:%d:%d", b->mesh, diag_source_name(b->loc.file), b->loc.line,
			        b->loc.col);
		fprintf(stderr, ": %d primitives, %d nodes, %d leaves, depth %d, SAH cost %.2f, built in %.1f ms, "
		        "%.2f MB\n", b->prims, b->nodes, b->leaves, b->depth, b->sah_cost, b->build_ms,
		        b->bytes / 1048576.0);
	}
	if (lr->layout == LOWER_LAYOUT_WIDE)
		fprintf(stderr, "bvh: layout wide: %d nodes of 4 children and %d blocks of 4 mesh triangles, %.2f MB "
		        "(binary: %d nodes, %.2f MB, and the triangles)\n",
		        lr->n_wnodes, lr->n_wblocks, lr->dev_node_bytes / 1048576.0, lr->n_nodes,
		        lr->n_nodes * sizeof(bvh_node) / 1048576.0);
	else
		fprintf(stderr, "bvh: layout binary: %d nodes, %.2f MB\n", lr->n_nodes, lr->dev_node_bytes / 1048576.0);
}

static void print_ray_stats(const render_stats *st)
{
	static const char *const kinds[RAY_KINDS] = { "camera", "bounce", "shadow" };   /* ORDER RAY_ */
	uint64_t rays = 0, tests = 0;
	for (int k = 0; k < RAY_KINDS; k++) {
		uint64_t n = st->counts[COUNT_RAYS + k];
		rays += n;
		tests += st->counts[COUNT_NODES + k] + st->counts[COUNT_PRIMS + k];
		fprintf(stderr, "rays: %s: %llu rays, %.2f node tests and %.2f primitive tests per ray\n", kinds[k],
		        (unsigned long long)n, n ? (double)st->counts[COUNT_NODES + k] / n : 0,
		        n ? (double)st->counts[COUNT_PRIMS + k] / n : 0);
	}
	fprintf(stderr, "rays: all: %.2f tests per ray, %.2f tests per path (per pixel per sample)\n",
	        rays ? (double)tests / rays : 0, st->counts[COUNT_RAYS + RAY_CAMERA]
	        ? (double)tests / st->counts[COUNT_RAYS + RAY_CAMERA] : 0);
}

/* POV-Ray lights such a scene with its ambient term, and so does the Whitted
 * integrator; a path tracer sees black (unless a fog or a media glows). An
 * emitting surface counts whether or not the emitter table has a row for it: a
 * torus that emits is found by rays. */
static void warn_if_dark(const struct options *o, const scene *s, const lower_result *lr)
{
	const float *bg = s->has_sky ? s->sky : s->background;
	int glows = 0;
	for (int i = 0; i < lr->textures.n_media; i++) {
		const dev_media *m = &lr->textures.media[i];
		glows |= m->emission.x > 0 || m->emission.y > 0 || m->emission.z > 0;
	}
	for (int i = 0; i < lr->n_materials; i++) {
		const dev_material *m = &lr->materials[i];
		glows |= m->emission.x > 0 || m->emission.y > 0 || m->emission.z > 0;
		if (o->integrator == INTEGRATOR_WHITTED)
			glows |= m->ambient.x > 0 || m->ambient.y > 0 || m->ambient.z > 0;
	}
	if (lr->n_lights == 0 && lr->n_fogs == 0 && lr->n_rainbows == 0 && !glows && bg[0] <= 0 && bg[1] <= 0 &&
	    bg[2] <= 0)
		diag_warning(SRC_NOWHERE, "'%s' has no light_source, no emission and a black background: "
		             "the image will be black", o->scene);
}

/* --threads N: PoCL's CPU device reads its thread cap from the environment
 * when the platform is first opened, so it is set before that. */
static int set_threads(const struct options *o)
{
	char n[16];
	snprintf(n, sizeof n, "%d", o->threads);
	if (o->threads > 0 && setenv("POCL_MAX_PTHREAD_COUNT", n, 1) != 0) {
		fprintf(stderr, "eclat: --threads: %s\n", strerror(errno));
		return -1;
	}
	return 0;
}

/* An animation's frame, for the progress line and the closing lines, and the
 * names of its AOV files (numbered as its image is). */
struct frame_info {
	long frame, index, frames;
	double clock, seconds;   /* seconds: spent on the frames before */
	char *aov_file[MAX_AOVS];
};

/* The options that change pixels, as split_key records them: a part, or a
 * file to resume, made with others is refused. The number of samples is not
 * one of them: a render resumes to more, and merge checks its parts' own. */
static char *pixel_options(const struct options *o, const render_settings *rs, const struct frame_info *fi)
{
	static const char *const integrators[] = { "path", "naive", "whitted" };   /* ORDER INTEGRATOR_ */
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	if (!f)
		return NULL;
	fprintf(f, "width=%d\nheight=%d\nintegrator=%s\nseed=%d\nmax-depth=%d\nbvh=%d:%d:%d\n"
	        "skip-unsupported=%d\nclock=%.17g\nframe=%ld\n", rs->width, rs->height,
	        integrators[rs->integrator % 3], rs->seed, rs->max_depth, o->bvh, o->median_depth,
	        o->bvh_layout, o->skip_unsupported, fi->clock, fi->frame);
	for (int i = 0; i < o->n_declares; i++)
		fprintf(f, "declare=%s\n", o->declares[i]);
	if (o->no_sky_sampling)   /* only when off: parts made before the option still merge */
		fprintf(f, "sky-sampling=off\n");
	return fclose(f) == 0 ? text : (free(text), NULL);
}

/* What --sample-range, a region and --resume ask of the render (split_plan.c). */
static int plan_split(const struct options *o, const scene *s, const char *output, const int *part,
                      const split_inputs *in, const struct frame_info *fi, render_settings *rs, split_info *info,
                      int64_t **resumed)
{
	char *opts = pixel_options(o, rs, fi);
	split_request rq = { o->scene, output, o->resume, o->resume_output, o->range_first, o->range_count, part,
	                     o->n_aovs, opts, s->film_gamma, in };
	int rc = opts ? split_plan(&rq, rs, info, resumed) : -1;
	free(opts);
	return rc;
}

static int render_scene(const struct options *o, const scene *s, const char *output, const int *part,
                        const split_inputs *in, render_keep *keep, const struct frame_info *fi)
{
	lower_result lr;
	int aa = o->integrator == INTEGRATOR_WHITTED && o->pov.antialias == 1 ? o->pov.aa_method : 0;
	lower_options lo = { o->bvh, o->median_depth, o->bvh_layout, o->skip_unsupported, o->width, o->height,
	                     fi->frames > 1 ? render_keep_cache(keep) : NULL,
	                     o->integrator != INTEGRATOR_WHITTED ? LOWER_KERNELS_PATH
	                     : aa == 2                          ? LOWER_KERNELS_WHITTED_AA2
	                     : aa == 1                          ? LOWER_KERNELS_WHITTED_AA1
	                                                        : LOWER_KERNELS_WHITTED };
	int failed = lower_scene(s, &lo, &lr);
	if (!failed && o->stats)
		print_bvh_stats(s, &lr);
	if (failed || o->check) {
		int rc = failed || diag_error_count() > 0;
		lower_free(&lr);
		return rc;
	}
	warn_if_dark(o, s, &lr);   /* only when there is an image to warn about */
	if (o->no_sky_sampling)
		lr.params.sky_sampled = 0;
	if (o->pov.alpha)
		lower_background_alpha(s, &lr.params);
	split_info info = { 0 };
	struct output out = { output, o->scene, o->pov.bits, part, split_is_exr(output) ? &info : NULL, o->pov.alpha };
	/* deterministic: one sample is the image, anti-aliased (+A) as POV-Ray does */
	int whitted = o->integrator == INTEGRATOR_WHITTED;
	const cli_pov *pov = &o->pov;
	double aa_threshold = pov->aa_threshold < 0 ? 0 : pov->aa_threshold > 1 ? 1 : pov->aa_threshold;
	double jitter = !pov->jitter ? 0 : pov->jitter_amount < 0 ? 0 : pov->jitter_amount > 1 ? 1 : pov->jitter_amount;
	render_settings rs = {
		.width = o->width, .height = o->height, .samples = whitted ? 1 : o->samples, .seed = o->seed,
		.aa_method = pov->antialias == 1 ? pov->aa_method : 0, .aa_depth = pov->aa_depth,
		.aa_threshold = (float)aa_threshold, .aa_jitter = (float)jitter,
		.aa_gamma = (float)(pov->aa_gamma > 0 ? s->film_gamma / pov->aa_gamma : s->film_gamma),
		.max_depth = o->max_depth >= 0 ? o->max_depth
		           : s->max_trace_level > 0 ? s->max_trace_level : DEFAULT_MAX_DEPTH,
		.integrator = o->integrator, .adc_bailout = s->adc_bailout, .gamma = s->film_gamma, .quiet = o->quiet,
		.aov = needs_aov_buffer(o) || o->pov.alpha,   /* the alpha channel's sums are there */
		.time_limit = o->time_limit,
		.checkpoint = o->checkpoint, .on_checkpoint = write_film, .ctx = &out, .stop = &stop_signal,
		.frame = fi->frame, .frame_index = fi->index, .frames = fi->frames, .anim_seconds = fi->seconds,
	};
	device_ctx multi = { 0 };   /* several devices: only its name, for the summary */
	cl_program prog = NULL;
	film f = { 0 };
	render_stats st;
	int rc = 1;
	int64_t *resumed = NULL;
	catch_signals();
	int ran = -1;   /* 1: failed after some passes, whose samples f holds */
	int several = o->n_devices < 0 || o->n_devices > 1;
	if (window) {   /* several devices: render_multi adds their films up for it */
		rs.on_show = show_film;
		rs.show_ctx = window;
		rs.show_every = PREVIEW_EVERY;
	}
	int planned = plan_split(o, s, output, part, in, fi, &rs, &info, &resumed) == 0 &&
	              (keep->opened || set_threads(o) == 0);
	for (int i = -1; i < o->n_aovs && planned; i++)   /* see check_format: after the lowering, before the kernels */
		planned = check_format(i < 0 ? output : fi->aov_file[i], i < 0 && o->pov.alpha) == 0;
	if (planned && several)
		ran = render_multi(o->devices, o->n_devices < 0 ? 0 : o->n_devices, o->kernel_dir, &lr, &rs, &f, &st,
		                   multi.name, sizeof multi.name);
	else if (planned && (prog = render_keep_program(keep, o->device, o->kernel_dir, &lr)) != NULL)
		ran = render_run(&keep->dev, prog, &lr, &rs, &f, &st);
	if (ran >= 0) {
		if (!o->quiet && ran == 0 && fi->frames > 1)
			fprintf(stderr, "eclat: frame %ld (%ld of %ld), clock %g: '%s'\n", fi->frame, fi->index + 1,
			        fi->frames, fi->clock, output);
		if (!o->quiet && ran == 0)
			summary(&rs, &st, several ? &multi : &keep->dev);
		if (o->stats)
			print_ray_stats(&st);
		if (window)   /* a stop asked for now stops the frames after */
			preview_show(window, f.rgb);
		int wrote = write_film(&f, &out) == 0 && write_aovs(o, fi->aov_file, &f) == 0;
		if (wrote)
			rc = ran ? 1 : stop_signal ? 128 + stop_signal : 0;
		if (ran && wrote)
			fprintf(stderr, "eclat: the render failed after %ld samples per pixel; '%s' holds those\n",
			        st.samples, output);
		else if (wrote && st.samples < rs.samples)   /* said even with -q: the image is not what was asked */
			fprintf(stderr, "eclat: stopped early by %s: '%s' holds %ld of the %d samples per pixel asked for\n",
			        preview_stopped(window) ? "the preview window" : stop_signal == SIGINT ? "Ctrl-C (SIGINT)"
			        : stop_signal ? "SIGTERM"
			        : "--time-limit", output, st.samples, rs.samples);
		if (window && o->pause && !stop_signal && !preview_stopped(window))
			preview_pause(window, &stop_signal);
	}
	film_free(&f);
	free(resumed);
	split_key_free(&info.key);
	lower_free(&lr);
	return rc;
}

/* The declared name of an exported mesh: its file's stem, capitalised, with what
 * an identifier cannot hold turned into '_' ("bunny.ply" gives Bunny). */
static void mesh2_name(const char *path, char *name, size_t n)
{
	const char *base = strrchr(path, '/');
	base = base ? base + 1 : path;
	size_t k = 0;
	if (!isalpha((unsigned char)*base))
		name[k++] = 'M';
	for (; *base && *base != '.' && k + 1 < n; base++)
		name[k++] = isalnum((unsigned char)*base) ? *base : '_';
	name[k] = '\0';
	name[0] = (char)toupper((unsigned char)name[0]);
}

/* --export-mesh2 FILE: the mesh as a mesh2 include, on -o or standard output. */
static int export_mesh2(const struct options *o)
{
	scene_mesh m;
	char err[512], name[64];
	if (mesh_io_load(o->export_mesh2, (unsigned)o->mesh_time_limit, 0, &m, err, sizeof err)) {
		fprintf(stderr, "eclat: %s: %s\n", o->export_mesh2, err);
		return 1;
	}
	FILE *out = o->output ? fopen(o->output, "w") : stdout;
	int rc = 1;
	if (!out) {
		fprintf(stderr, "eclat: %s: %s\n", o->output, strerror(errno));
	} else {
		mesh2_name(o->export_mesh2, name, sizeof name);
		rc = mesh_io_write_mesh2(&m, name, o->export_mesh2, out) ? 1 : 0;
		if ((out != stdout && fclose(out)) || (out == stdout && fflush(out)))
			rc = 1;
		if (rc)
			fprintf(stderr, "eclat: could not write %s\n", o->output ? o->output : "the mesh2");
	}
	scene_mesh_free(&m);
	return rc;
}

static void set_clock(eval_options *e, const cli_frame *f)
{
	e->clock = f->clock;
	e->clock_delta = f->clock_delta;
	e->clock_on = f->clock_on;
	e->frame_number = f->frame;
	e->initial_frame = f->initial_frame;
	e->final_frame = f->final_frame;
	e->initial_clock = f->initial_clock;
	e->final_clock = f->final_clock;
}

static double seconds_since(const struct timespec *t0)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)(t.tv_sec - t0->tv_sec) + (t.tv_nsec - t0->tv_nsec) * 1e-9;
}

/* Where the files a frame reads are noted: its record of the scene (split.h)
 * and the depfile. */
struct reads {
	split_inputs inputs;
	depfile *deps;
};

static void note_read(const char *path, void *ctx)
{
	struct reads *r = ctx;
	split_note_input(path, &r->inputs);
	if (r->deps)
		depfile_on_read(r->deps, path);
}

/* The frames asked for, one after another, each evaluated anew at its clock,
 * as POV-Ray parses its scene anew for each; the device, the kernels and the
 * meshes' BVHs stay from frame to frame. --check looks at the first frame. */
static int render_frames(const struct options *o, const ast_node *tree, eval_options *eopt, cli_frame *frame,
                         const int *part)
{
	render_keep keep = { 0 };
	struct timespec t0;
	clock_gettime(CLOCK_MONOTONIC, &t0);
	long frames = o->check ? 1 : frame->frames;
	eopt->mesh_cache = frames > 1 ? mesh_io_cache_new() : NULL;
	depfile *deps = o->depfile ? depfile_new() : NULL;
	int rc = o->depfile && (!deps || depfile_add(deps, DEPFILE_INPUT, o->scene));
	struct reads reads = { { 0 }, deps };
	eopt->on_read = note_read;
	eopt->on_read_ctx = &reads;
	window = o->preview && !o->check && rc == 0 ? preview_open(o->width, o->height, o->scene) : NULL;
	for (long k = 0; k < frames && rc == 0 && !stop_signal && !preview_stopped(window); k++) {
		cli_frame_goto(frame, frame->first + k * frame->step);
		char *output = cli_pov_output(&o->pov, frame, o->scene, o->output);
		rc = !output || (!o->check && check_output(o->scene, output)) ||
		     (deps && depfile_add(deps, DEPFILE_TARGET, output));
		set_clock(eopt, frame);
		struct frame_info fi = { frame->frame, k, frames, frame->clock, seconds_since(&t0), { 0 } };
		for (int i = 0; i < o->n_aovs && rc == 0; i++)   /* an animation's AOVs numbered as its images */
			rc = !(fi.aov_file[i] = cli_pov_output(&o->pov, frame, o->scene, o->aov_file[i])) ||
			     (deps && depfile_add(deps, DEPFILE_TARGET, fi.aov_file[i]));
		scene s;
		scene_init(&s);
		split_inputs_free(&reads.inputs);   /* each frame's record names the files it read */
		reads.inputs = (split_inputs){ 0 };
		int evaluated = rc == 0 ? eval_scene(tree, &s, eopt) : -1;
		device_points_forget(eopt->pattern_ctx);   /* the next frame numbers its pigments anew */
		if (evaluated == 0 && diag_error_count() == 0) {
			if (o->dump_scene)
				scene_dump(&s, stdout);
			rc = render_scene(o, &s, output, part, &reads.inputs, &keep, &fi);
		} else {
			rc = 1;
		}
		scene_free(&s);
		free(output);
		for (int i = 0; i < o->n_aovs; i++)
			free(fi.aov_file[i]);
		mesh_io_cache_sweep(eopt->mesh_cache);
	}
	int files = mesh_io_cache_hits(eopt->mesh_cache), bvhs = lower_cache_hits(keep.bvhs);
	if (frames > 1 && !o->quiet && rc == 0)
		fprintf(stderr, "eclat: %ld frames in %.2f s (the kernels built %d time%s; %d mesh file%s and %d mesh "
		        "BVH%s reused)\n", frames, seconds_since(&t0), keep.builds, keep.builds == 1 ? "" : "s", files,
		        files == 1 ? "" : "s", bvhs, bvhs == 1 ? "" : "s");
	if (deps && rc == 0)
		rc = depfile_write(deps, o->depfile) ? 1 : 0;
	depfile_free(deps);
	split_inputs_free(&reads.inputs);
	eopt->on_read = NULL;
	mesh_io_cache_free(eopt->mesh_cache);
	eopt->mesh_cache = NULL;
	render_keep_free(&keep);
	preview_close(window);
	window = NULL;
	return rc;
}

/* The scene read and rendered (or checked, or its tree dumped). */
static int run_scene(const struct options *o, cli_frame *frame, const int *part)
{
	int rc;
	eval_options eopt = eval_options_default();
	eopt.include_dirs = o->include_dirs;
	eopt.n_include_dirs = o->n_include_dirs;
	eopt.declares = o->declares;
	eopt.n_declares = o->n_declares;
	eopt.skip_unsupported = o->skip_unsupported;
	eopt.max_include_depth = o->max_include_depth;
	eopt.max_macro_depth = o->max_macro_depth;
	eopt.max_loop_iterations = o->max_loop_iterations;
	eopt.mesh_time_limit = (unsigned)o->mesh_time_limit;
	eopt.memory_limit = o->memory_limit;
	eopt.io_security = o->io_security;
	eopt.io_current_folder = true;
	eopt.io_read_dirs = o->io_read_dirs;
	eopt.n_io_read_dirs = o->n_io_read_dirs;
	eopt.io_write_dirs = o->io_write_dirs;
	eopt.n_io_write_dirs = o->n_io_write_dirs;
	eopt.image_width = o->width;
	eopt.image_height = o->height;
	ast_node *tree = parse_file(o->scene, SRC_NOWHERE);
	if (!tree)
		rc = 1;
	else if (o->dump_ast) {
		ast_dump(tree, stdout);
		rc = 0;
	} else {
		device_points *points = device_points_new(o->device, o->kernel_dir);
		eopt.pattern_at = points ? device_points_eval : NULL;
		eopt.pattern_ctx = points;
		rc = render_frames(o, tree, &eopt, frame, part);
		device_points_free(points);
	}
	ast_free(tree);
	diag_free_all();
	return rc;
}

int main(int argc, char **argv)
{
	if (argc > 1 && strcmp(argv[1], "merge") == 0)
		return merge_main(argc - 1, argv + 1);
	struct options o;
	parse_options(argc, argv, &o);
	if (o.list_devices)
		return set_threads(&o) || device_list(stdout) < 0 ? 1 : 0;
	if (o.export_mesh2)
		return export_mesh2(&o);

	cli_frame frame;
	cli_pov_frame(&o.pov, &frame);
	char *output = cli_pov_output(&o.pov, &frame, o.scene, o.output);
	if (!output)
		return 1;
	int rc = 1;
	int bad_output = !o.dump_ast && !o.check && check_output(o.scene, output);
	for (int i = 0; i < o.n_aovs && !bad_output && !o.check && !o.dump_ast; i++)
		bad_output = check_output(o.scene, o.aov_file[i]);
	if (!bad_output && !o.dump_ast && !o.check)
		image_module_start();   /* the image will be written: OpenImageIO loads while the scene is read */
	int part[4], has_part = cli_pov_region(&o.pov, o.width, o.height, part);
	free(output);
	if (!bad_output && has_part >= 0)
		rc = run_scene(&o, &frame, has_part ? part : NULL);
	image_module_settle();   /* exit() must not meet a load of the module half made */
	return rc;
}
