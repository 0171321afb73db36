/* Shared declaration of the two-TU link test (cfg_two_tu_main.c, cfg_two_tu_other.c). */
#ifndef CFG_TWO_TU_H
#define CFG_TWO_TU_H
int other_tu_first_hit(float *tf, double *td, const char **msg);
#endif
