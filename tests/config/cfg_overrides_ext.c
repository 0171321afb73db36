/* The other translation unit of the CYL_DEF test: it does not include cylinder_isect.h and
 * reaches cyl_strerror through its own prototype, which links only if cfg_overrides.c defined
 * it with external linkage (CYL_DEF defined empty there). */
const char *cyl_strerror(int code);
const char *ext_strerror(int code);

const char *ext_strerror(int code) { return cyl_strerror(code); }
