/* SPDX-License-Identifier: BSD-3-Clause */
/* The example models (the .bg files in examples/) in a fixed order: the file names, each
 * malloc'd. Shared by the tests that run over every example. */
#ifndef BG_TEST_EXAMPLES_LIST_H
#define BG_TEST_EXAMPLES_LIST_H
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

static inline int bg_t_list_examples(char **names, int cap) {
  DIR *dir = opendir(BG_SOURCE_DIR "/examples");
  if (!dir) return 0;
  int n = 0;
  for (struct dirent *e; (e = readdir(dir)) && n < cap;) {
    size_t len = strlen(e->d_name);
    if (len > 3 && !strcmp(e->d_name + len - 3, ".bg")) names[n++] = strdup(e->d_name);
  }
  closedir(dir);
  /* a fixed order: readdir's is the file system's */
  for (int i = 1; i < n; i++)
    for (int j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
      char *t = names[j];
      names[j] = names[j - 1], names[j - 1] = t;
    }
  return n;
}
#endif
