/* compare_dumps a.bin b.bin [N]: compares two dump files pixel by pixel
 * (colour and depth) and prints one summary line; with N, also the first N
 * differences. Exit status 1 if anything differs. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv) {
  if (argc < 3) { fprintf(stderr, "usage: compare_dumps a.bin b.bin [N]\n"); return 2; }
  FILE *a = fopen(argv[1], "rb"), *b = fopen(argv[2], "rb");
  if (!a || !b) { perror("compare_dumps"); return 2; }
  const long verbose = argc > 3 ? atol(argv[3]) : 0;
  long frames = 0, pixels = 0, drawn = 0, colorDiff = 0, maxDiff = 0, depthDiff = 0;
  for (;;) {
    int W, H, W2, H2;
    if (fread(&W, 4, 1, a) != 1) break;
    if (fread(&H, 4, 1, a) != 1 || fread(&W2, 4, 1, b) != 1 || fread(&H2, 4, 1, b) != 1 || W != W2 || H != H2) {
      fprintf(stderr, "compare_dumps: the files do not match in layout\n");
      return 2;
    }
    size_t n = (size_t)W * H;
    unsigned char *ca = malloc(n * 4), *cb = malloc(n * 4);
    unsigned *da = malloc(n * 4), *db = malloc(n * 4);
    if (fread(ca, 4, n, a) != n || fread(cb, 4, n, b) != n || fread(da, 4, n, a) != n || fread(db, 4, n, b) != n) {
      fprintf(stderr, "compare_dumps: short file\n");
      return 2;
    }
    unsigned clear; /* the first file's most common pixel, sampled: the clear colour */
    long best = -1;
    for (size_t j = 0; j < n; j += n / 64 + 1) {
      unsigned v; long c = 0;
      memcpy(&v, ca + j * 4, 4);
      for (size_t i = 0; i < n; i++) { unsigned u; memcpy(&u, ca + i * 4, 4); c += u == v; }
      if (c > best) best = c, clear = v;
    }
    for (size_t i = 0; i < n; i++) {
      unsigned u;
      memcpy(&u, ca + i * 4, 4);
      drawn += u != clear;
      int d = 0;
      for (int k = 0; k < 4; k++) { int e = abs(ca[i * 4 + k] - cb[i * 4 + k]); if (e > d) d = e; }
      if (d) {
        colorDiff++;
        if (colorDiff <= verbose)
          printf("frame %ld pixel (%zu,%zu): %d %d %d %d vs %d %d %d %d\n", frames, i % W, i / W, ca[i * 4],
                 ca[i * 4 + 1], ca[i * 4 + 2], ca[i * 4 + 3], cb[i * 4], cb[i * 4 + 1], cb[i * 4 + 2], cb[i * 4 + 3]);
      }
      if (d > maxDiff) maxDiff = d;
      if (da[i] != db[i]) {
        depthDiff++;
        if (depthDiff <= verbose) printf("frame %ld depth (%zu,%zu): %06x vs %06x\n", frames, i % W, i / W, da[i], db[i]);
      }
    }
    pixels += n;
    frames++;
    free(ca); free(cb); free(da); free(db);
  }
  printf("frames %ld pixels %ld drawn %ld colour-differences %ld (max %ld) depth-differences %ld\n", frames, pixels,
         drawn, colorDiff, maxDiff, depthDiff);
  return colorDiff || depthDiff ? 1 : 0;
}
