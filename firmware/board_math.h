/* The board's double sin, cos, exp and expm1 (board_math.c: why and how accurate). The
 * firmware's programs link them as libm's sin, cos, exp and expm1 (board_libm.c); the x86
 * test checks them against glibc's under these names. */
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

double feel_board_sin(double x);
double feel_board_cos(double x);
double feel_board_exp(double x);
double feel_board_expm1(double x);

#ifdef __cplusplus
}
#endif
