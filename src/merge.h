/* merge.h: eclat merge PART.exr... -o IMAGE, the image of one render from the
 * parts of a split one. */
#ifndef ECLAT_MERGE_H
#define ECLAT_MERGE_H

/* argv[0] is "merge". Returns the exit status: 0, or 1 after saying which
 * part is wrong and how, with nothing written. */
int merge_main(int argc, char **argv);

#endif
