/* image_table.h: the functions of image.h and split.h that need OpenImageIO,
 * as eclat finds them in its module eclat-oiio.so (src/image_table.c).
 *
 * Loading OpenImageIO loads some 280 libraries it depends on (OpenVDB, GDAL,
 * DICOM...), 0.15 s of relocations at every start of a program that links
 * it. eclat does not link it: src/image_module.c loads the module on a thread
 * of its own while the scene is read, or at the first call, and each function
 * of image.h and split.h below is a call through this table. The test
 * programs and fuzz targets link src/image_oiio.cpp and src/image_split.cpp
 * as they are. */
#ifndef ECLAT_IMAGE_TABLE_H
#define ECLAT_IMAGE_TABLE_H

#include "image.h"
#include "split.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A module of another build is refused: its abi or its sizes differ. */
#define IMAGE_TABLE_ABI 1
#define IMAGE_TABLE_SYMBOL "eclat_image_table"
#define IMAGE_MODULE_NAME "eclat-oiio.so"

typedef struct {
	int abi;
	size_t size, meta_size, data_size, split_size;   /* sizeof the table, image_meta, image_data, split_info */
	int (*format_known)(const char *path);
	int (*format_alpha)(const char *path);
	void (*temp_path)(const char *path, char *out, size_t n);
	int (*finish)(const char *tmp, const char *path, const char *write_error, int width, int height, char *err,
	              size_t errlen);
	int (*write)(const char *path, const float *rgb, int width, int height, const image_meta *meta, char *err,
	             size_t errlen);
	void (*encode8)(const float *linear, size_t n, unsigned char *out);
	int (*write_heat)(const char *path, const float *heat, int width, int height, const image_meta *meta,
	                  double *mean, char *err, size_t errlen);
	int (*read_here)(const char *path, long max_texels, image_data *out, char *err, size_t errlen);
	int (*split_write)(const char *path, const float *rgb, const int64_t *sums, const split_info *info, char *err,
	                   size_t errlen);
	int (*split_read_here)(const char *path, split_info *info, int64_t **sums, char *err, size_t errlen);
} image_table;

/* The module's one exported symbol. */
const image_table *eclat_image_table(void);

/* eclat's side (src/image_module.c). image_module_start begins loading the
 * module on a thread of its own; image_module_settle waits for that load when
 * one was started (before a fork: a child must not inherit a half-made load);
 * image_module_error is NULL when the module is there, else why not (and
 * loads it first). */
void image_module_start(void);
void image_module_settle(void);
const char *image_module_error(void);

#ifdef __cplusplus
}
#endif

#endif
