/* SPDX-License-Identifier: BSD-3-Clause */
/* A deterministic stand-in for libFuzzer's main, for builds without clang's
 * -fsanitize=fuzzer (the test suite; any compiler). It runs every input of
 * the corpus once, then -runs N mutants made with a fixed-seed generator:
 * the same corpus, seed and N give the same inputs on every machine.
 *
 *   fuzz_parse [-runs N] [-seed S] [-dict FILE] [-timeout SEC] CORPUS...
 *
 * CORPUS: files or folders of seed models. Before each input runs it is
 * saved to $BG_FUZZ_SAVE (when set), so a crash or a hang (SIGALRM after
 * -timeout seconds, default 10) leaves its reproducer behind. */
#include <dirent.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz_common.h"

typedef struct blob {
  char *p;
  size_t n;
} blob;

typedef struct blobs {
  blob *v;
  int n, cap;
} blobs;

static uint64_t rng_state = 0x9E3779B97F4A7C15u;
static uint64_t rng(void) { /* xorshift64* */
  rng_state ^= rng_state >> 12, rng_state ^= rng_state << 25, rng_state ^= rng_state >> 27;
  return rng_state * 0x2545F4914F6CDD1Du;
}
static size_t below(size_t n) { return n ? (size_t)(rng() % n) : 0; }

static void push(blobs *b, char *p, size_t n) {
  if (b->n == b->cap) {
    b->cap = b->cap ? 2 * b->cap : 64;
    b->v = realloc(b->v, (size_t)b->cap * sizeof *b->v);
    if (!b->v) abort();
  }
  b->v[b->n++] = (blob){p, n};
}

static void load_file(blobs *b, const char *path) {
  size_t n;
  char *p = bg_read_file(path, &n);
  if (p && n <= FUZZ_MAX_LEN) push(b, p, n);
  else free(p);
}

static int by_name(const void *a, const void *b) {
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* A folder's files in name order, so the corpus order is the same everywhere. */
static void load_path(blobs *b, const char *path) {
  struct stat st;
  if (stat(path, &st) != 0) return;
  if (!S_ISDIR(st.st_mode)) {
    load_file(b, path);
    return;
  }
  DIR *d = opendir(path);
  char **names = NULL;
  int n = 0;
  for (struct dirent *e; d && (e = readdir(d));) {
    if (e->d_name[0] == '.') continue;
    names = realloc(names, (size_t)(n + 1) * sizeof *names);
    size_t len = strlen(path) + strlen(e->d_name) + 2;
    names[n] = malloc(len);
    snprintf(names[n++], len, "%s/%s", path, e->d_name);
  }
  if (d) closedir(d);
  if (n > 1) qsort(names, (size_t)n, sizeof *names, by_name);
  for (int i = 0; i < n; i++) load_path(b, names[i]), free(names[i]);
  free(names);
}

/* libFuzzer's dictionary format: one "quoted word" per line, # comments. */
static void load_dict(blobs *b, const char *path) {
  char *text = bg_read_file(path, NULL);
  for (char *line = text ? strtok(text, "\n") : NULL; line; line = strtok(NULL, "\n")) {
    char *q = strchr(line, '"'), *e = strrchr(line, '"');
    if (line[0] == '#' || !q || e <= q) continue;
    char *w = malloc((size_t)(e - q));
    size_t n = 0;
    for (char *c = q + 1; c < e; c++) {
      if (*c == '\\' && c + 3 < e && c[1] == 'x') {
        w[n++] = (char)strtol((char[]){c[2], c[3], 0}, NULL, 16);
        c += 3;
      } else if (*c == '\\' && c + 1 < e) w[n++] = *++c;
      else w[n++] = *c;
    }
    push(b, w, n);
  }
  free(text);
}

/* ----------------------------------------------------------- mutations */
typedef struct buf {
  char p[FUZZ_MAX_LEN];
  size_t n;
} buf;

static void insert(buf *b, size_t at, const char *s, size_t n) {
  if (b->n + n > sizeof b->p) n = sizeof b->p - b->n;
  memmove(b->p + at + n, b->p + at, b->n - at);
  memcpy(b->p + at, s, n);
  b->n += n;
}

static void erase(buf *b, size_t at, size_t n) {
  if (at + n > b->n) n = b->n - at;
  memmove(b->p + at, b->p + at + n, b->n - at - n);
  b->n -= n;
}

/* Numbers that have found bugs in parsers and grids before. */
static const char *const odd_numbers[] = {"0", "-1", "1e308", "1e-300", "4294967298", "2147483648",
                                          "1e9", "1000000001", "nan", "inf", "0.0", "1e999",
                                          "9999999999999999999999", "-0", "3"};

static void mutate_once(buf *b, const blobs *corpus, const blobs *dict) {
  size_t at = below(b->n + 1);
  switch (below(9)) {
  case 0: if (b->n) b->p[below(b->n)] ^= (char)(1u << below(8)); break;
  case 1: if (b->n) b->p[below(b->n)] = (char)below(256); break;
  case 2: erase(b, at, 1 + below(16)); break;
  case 3: { /* duplicate a chunk (lines, tokens) */
    size_t from = below(b->n + 1), n = below(b->n - from + 1) % 64;
    char tmp[64];
    memcpy(tmp, b->p + from, n);
    insert(b, at, tmp, n);
    break;
  }
  case 4: case 5:
    if (dict->n) {
      const blob *w = &dict->v[below((size_t)dict->n)];
      insert(b, at, w->p, w->n);
    }
    break;
  case 6: { /* a whole line of another seed */
    const blob *o = &corpus->v[below((size_t)corpus->n)];
    size_t from = below(o->n + 1), to = from;
    while (to < o->n && o->p[to] != '\n') to++;
    insert(b, at, o->p + from, to - from + (to < o->n));
    break;
  }
  case 7: { /* an odd number in place of a digit run */
    size_t s = at;
    while (s < b->n && !(b->p[s] >= '0' && b->p[s] <= '9')) s++;
    size_t e = s;
    while (e < b->n && b->p[e] >= '0' && b->p[e] <= '9') e++;
    const char *num = odd_numbers[below(sizeof odd_numbers / sizeof *odd_numbers)];
    erase(b, s, e - s);
    insert(b, s, num, strlen(num));
    break;
  }
  default: insert(b, at, "\n", 1); break;
  }
}

/* ----------------------------------------------------------------- main */
static const char *save_path;

static void run_one(const char *p, size_t n) {
  if (save_path) {
    FILE *f = fopen(save_path, "wb");
    if (f) fwrite(p, 1, n, f), fclose(f);
  }
  LLVMFuzzerTestOneInput((const uint8_t *)p, n);
}

int main(int argc, char **argv) {
  long runs = 0, timeout = 10;
  unsigned long long seed = 1;
  blobs corpus = {0}, dict = {0};
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "-runs") && i + 1 < argc) runs = atol(argv[++i]);
    else if (!strcmp(argv[i], "-seed") && i + 1 < argc) seed = strtoull(argv[++i], NULL, 10);
    else if (!strcmp(argv[i], "-dict") && i + 1 < argc) load_dict(&dict, argv[++i]);
    else if (!strcmp(argv[i], "-timeout") && i + 1 < argc) timeout = atol(argv[++i]);
    else load_path(&corpus, argv[i]);
  }
  if (corpus.n == 0) {
    fprintf(stderr, "usage: %s [-runs N] [-seed S] [-dict FILE] [-timeout SEC] CORPUS...\n", argv[0]);
    return 2;
  }
  save_path = getenv("BG_FUZZ_SAVE");
  rng_state ^= seed * 0x100000001B3u;
  signal(SIGALRM, SIG_DFL); /* a hang dies of SIGALRM */
  for (int i = 0; i < corpus.n; i++) alarm((unsigned)timeout), run_one(corpus.v[i].p, corpus.v[i].n);
  static buf b;
  for (long r = 0; r < runs; r++) {
    const blob *s = &corpus.v[below((size_t)corpus.n)];
    memcpy(b.p, s->p, s->n);
    b.n = s->n;
    for (size_t k = 1 + below(4); k > 0; k--) mutate_once(&b, &corpus, &dict);
    alarm((unsigned)timeout);
    run_one(b.p, b.n);
  }
  alarm(0);
  printf("%d seeds and %ld mutants ran\n", corpus.n, runs);
  for (int i = 0; i < corpus.n; i++) free(corpus.v[i].p);
  for (int i = 0; i < dict.n; i++) free(dict.v[i].p);
  free(corpus.v), free(dict.v);
  return 0;
}
