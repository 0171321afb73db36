/* Included first (-include) by the forced_inline runner: the header's advice for callers that
   call an entry point from several places (API CONTRACT, options) must compile cleanly. */
#if defined(__GNUC__) || defined(__clang__)
#define CYL_DEF static inline __attribute__((always_inline))
#endif
