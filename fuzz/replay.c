/* replay.c: replays the committed corpora without libFuzzer, as a Unity runner inside
 * `make test`: one Unity test per corpus file, named after the file, failing with the violated
 * invariant. Built with gcc (strict C99 warnings) and with clang's ASan/UBSan by mk/fuzz.mk.
 *
 *   build/fuzz/replay-gcc [RAW_DIR [GRID_DIR]]    defaults: fuzz/corpus fuzz/corpus_grid
 *   build/fuzz/replay-gcc -v FILE...              replay single files (raw layout)
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"

#define FZ_FAIL(msg) TEST_FAIL_MESSAGE(msg)
#include "fuzz_check.h"
#include "fuzz_grid.h"

#ifndef FUZZ_CORPUS_DIR
#define FUZZ_CORPUS_DIR "fuzz/corpus"
#endif
#ifndef FUZZ_GRID_DIR
#define FUZZ_GRID_DIR "fuzz/corpus_grid"
#endif

/* Corpus inputs are small (the raw layout is 132 bytes); anything longer is cut here, as
 * libFuzzer's -max_len would. */
#define FZ_MAX_INPUT 4096

void setUp(void) {}
void tearDown(void) {}

static unsigned char cur_buf[FZ_MAX_INPUT];
static size_t cur_len;
static int cur_grid;

static void replay_current(void)
{
  if (cur_grid) {
    unsigned char raw[FZ_HEADER_BYTES + FZ_NUMS * 8];
    size_t n = fz_grid_to_raw(cur_buf, cur_len, raw, sizeof raw);
    fz_one(raw, n);
  } else {
    fz_one(cur_buf, cur_len);
  }
}

static int load(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  cur_len = fread(cur_buf, 1, sizeof cur_buf, f);
  fclose(f);
  return 1;
}

static int cmp_names(const void *x, const void *y)
{
  return strcmp(*(const char *const *)x, *(const char *const *)y);
}

/* One Unity test per file of dir, in name order; returns the number of files. */
static int replay_dir(const char *dir, int grid)
{
  DIR *dp = opendir(dir);
  struct dirent *de;
  char **names = NULL;
  size_t n = 0, cap = 0, i;
  if (!dp) {
    printf("note: no corpus directory %s\n", dir);
    return 0;
  }
  while ((de = readdir(dp)) != NULL) {
    if (de->d_name[0] == '.') continue;
    if (n == cap) {
      char **nn;
      cap = cap ? 2 * cap : 256;
      nn = (char **)realloc(names, cap * sizeof *names);
      if (!nn) break;
      names = nn;
    }
    names[n] = (char *)malloc(strlen(de->d_name) + 1);
    if (!names[n]) break;
    strcpy(names[n], de->d_name);
    n++;
  }
  closedir(dp);
  if (n) qsort(names, n, sizeof *names, cmp_names);
  for (i = 0; i < n; i++) {
    static char path[4096], label[4200];
    snprintf(path, sizeof path, "%s/%s", dir, names[i]);
    snprintf(label, sizeof label, "%s%s", grid ? "grid:" : "", names[i]);
    cur_grid = grid;
    if (!load(path)) {
      printf("note: cannot read %s\n", path);
      continue;
    }
    UnityDefaultTestRun(replay_current, label, 0);
    free(names[i]);
  }
  free(names);
  return (int)n;
}

int main(int argc, char **argv)
{
  int nraw = 0, ngrid = 0, i;
  UNITY_BEGIN();
  if (argc > 2 && strcmp(argv[1], "-v") == 0) {
    for (i = 2; i < argc; i++) {
      cur_grid = 0;
      if (load(argv[i])) UnityDefaultTestRun(replay_current, argv[i], 0);
    }
  } else {
    nraw = replay_dir(argc > 1 ? argv[1] : FUZZ_CORPUS_DIR, 0);
    ngrid = replay_dir(argc > 2 ? argv[2] : FUZZ_GRID_DIR, 1);
  }
  printf("replayed %d raw + %d grid inputs: %lu valid, %lu with a hit, %lu float/double decisions "
         "compared, %lu exact-reference checks",
         nraw, ngrid, fz_stat.valid, fz_stat.hits, fz_stat.cond_checked, fz_stat.ref_checked);
#ifdef FUZZ_HAVE_REF
  printf(" (%lu with every decision compared)", fz_ref_decisions);
#endif
  printf("\n");
  return UNITY_END();
}
