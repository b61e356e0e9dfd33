/* suggest.h: "did you mean" for a misspelt word (a directive, a long option):
 * the distance between two words, counting an insertion, a deletion, a
 * change or two neighbours swapped as one step each (Damerau's), and whether
 * it is small enough for the longer word to be a slip of the other. */
#ifndef ECLAT_SUGGEST_H
#define ECLAT_SUGGEST_H

int suggest_distance(const char *a, const char *b);
/* Keeps in *best the candidate nearest word (ties: the first), when near
 * enough: one step in a word of up to 4 letters, two in a longer one. Start
 * with *best NULL and *dist 0. */
void suggest_consider(const char *word, const char *candidate, const char **best, int *dist);

#endif
