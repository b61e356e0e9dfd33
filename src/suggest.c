/* suggest.c: the nearest known word to a misspelt one. */
#include <stdlib.h>
#include <string.h>

#include "suggest.h"

#define MAX_WORD 64

int suggest_distance(const char *a, const char *b)
{
	int n = (int)strlen(a), m = (int)strlen(b);
	if (n > MAX_WORD || m > MAX_WORD)
		return MAX_WORD;
	int d[MAX_WORD + 1][MAX_WORD + 1];
	for (int i = 0; i <= n; i++)
		d[i][0] = i;
	for (int j = 0; j <= m; j++)
		d[0][j] = j;
	for (int i = 1; i <= n; i++)
		for (int j = 1; j <= m; j++) {
			int cost = a[i - 1] != b[j - 1];
			int v = d[i - 1][j] + 1;
			if (d[i][j - 1] + 1 < v)
				v = d[i][j - 1] + 1;
			if (d[i - 1][j - 1] + cost < v)
				v = d[i - 1][j - 1] + cost;
			if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < v)
				v = d[i - 2][j - 2] + 1;   /* two neighbours swapped */
			d[i][j] = v;
		}
	return d[n][m];
}

void suggest_consider(const char *word, const char *candidate, const char **best, int *dist)
{
	int limit = strlen(word) <= 4 ? 1 : 2;
	int k = suggest_distance(word, candidate);
	if (k > 0 && k <= limit && (!*best || k < *dist)) {
		*best = candidate;
		*dist = k;
	}
}
