/* png_io.h: 8-bit RGB images to and from PNG files through Debian's libpng, and the image
   comparison the example tests use. Shared by viewer.c, pngcmp.c and test_examples.c. */
#ifndef PNG_IO_H
#define PNG_IO_H

#include <png.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct image {
    int w, h;
    unsigned char *rgb; /* w*h*3 bytes, rows top to bottom */
} image;

/* Returns 0 on success. (static inline: each user takes only what it needs.) */
static inline int png_write_rgb(const char *path, const image *img)
{
    FILE *f = fopen(path, "wb");
    png_structp png;
    png_infop info;
    int y;
    if (!f) return -1;
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png ? png_create_info_struct(png) : NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)img->w, (png_uint_32)img->h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < img->h; y++)
        png_write_row(png, img->rgb + (size_t)y * (size_t)img->w * 3);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return fclose(f) == 0 ? 0 : -1;
}

/* Reads any PNG as 8-bit RGB (palette, grey, 16-bit and alpha are converted; alpha dropped).
   Returns 0 on success; the caller frees img->rgb. */
static inline int png_read_rgb(const char *path, image *img)
{
    FILE *f = fopen(path, "rb");
    png_structp png;
    png_infop info;
    unsigned char *volatile rgb = NULL;
    png_uint_32 w, h, y;
    if (!f) return -1;
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png ? png_create_info_struct(png) : NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        free(rgb);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_read_info(png, info);
    png_set_expand(png);
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_read_update_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 3) png_error(png, "not RGB8");
    rgb = (unsigned char *)malloc((size_t)w * h * 3);
    if (!rgb) png_error(png, "out of memory");
    for (y = 0; y < h; y++) png_read_row(png, rgb + (size_t)y * w * 3, NULL);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    img->w = (int)w;
    img->h = (int)h;
    img->rgb = rgb;
    return 0;
}

/* Number of pixels where some channel differs by more than tol_levels (of 255); -1 when the
   sizes differ. *max_diff receives the largest channel difference seen. */
static inline long image_count_diff(const image *a, const image *b, int tol_levels, int *max_diff)
{
    long bad = 0;
    size_t i, n;
    int c;
    *max_diff = 0;
    if (a->w != b->w || a->h != b->h) return -1;
    n = (size_t)a->w * (size_t)a->h;
    for (i = 0; i < n; i++) {
        int worst = 0;
        for (c = 0; c < 3; c++) {
            int d = abs((int)a->rgb[3 * i + (size_t)c] - (int)b->rgb[3 * i + (size_t)c]);
            if (d > worst) worst = d;
        }
        if (worst > *max_diff) *max_diff = worst;
        if (worst > tol_levels) bad++;
    }
    return bad;
}

#endif
