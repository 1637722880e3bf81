/* libm's double sin, cos, exp and expm1 on the board are board_math.c's: linked before
 * newlib's libm, these definitions keep its versions (8.3 KB of flash with their argument
 * reduction and tables) out of the image. Only the firmware's programs link this file. */
#include <math.h>

#include "board_math.h"

double sin(double x) { return feel_board_sin(x); }
double cos(double x) { return feel_board_cos(x); }
double exp(double x) { return feel_board_exp(x); }
double expm1(double x) { return feel_board_expm1(x); }
