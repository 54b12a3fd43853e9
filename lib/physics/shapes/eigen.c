/* eigen.c: the principal moments and axes of an inertia tensor, by the
 * cyclic Jacobi method for a symmetric 3×3 matrix (Golub and Van Loan (2013),
 * Matrix Computations, 4th ed., section 8.5: the rotation of Algorithm 8.5.1
 * zeroes one off-diagonal element, a sweep zeroes each in turn, and the
 * off-diagonal norm falls quadratically once small). Jacobi's method was
 * chosen for its accuracy, which Demmel and Veselić (1992), "Jacobi's method
 * is more accurate than QR", SIAM J. Matrix Anal. Appl. 13, 1204-1245, prove
 * relative for positive definite matrices such as an inertia tensor, and
 * for being short: a 3×3 matrix needs a few sweeps. */
#include <math.h>

#include "physics/shapes/shapes.h"

void dm_sym3_eigen(double a[3][3], double val[3], double vec[3][3])
{
    double A[3][3], V[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int j = 0; j < 3; j++)
        for (int k = j; k < 3; k++)
            A[j][k] = A[k][j] = a[j][k];
    /* Sweeps until every off-diagonal element is below the round-off of the
     * two diagonal ones it couples (Press et al. (2007), Numerical Recipes,
     * 3rd ed., section 11.1's test), at most 50 (a few are seen). */
    for (int sweep = 0; sweep < 50; sweep++) {
        int rotated = 0;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                double apq = A[p][q];
                if (fabs(A[p][p]) + 100.0 * fabs(apq) == fabs(A[p][p]) &&
                    fabs(A[q][q]) + 100.0 * fabs(apq) == fabs(A[q][q])) {
                    A[p][q] = A[q][p] = 0.0; /* below the round-off of both */
                    continue;
                }
                double tau = (A[q][q] - A[p][p]) / (2.0 * apq);
                double t = (tau >= 0.0 ? 1.0 : -1.0) / (fabs(tau) + sqrt(1.0 + tau * tau));
                double cs = 1.0 / sqrt(1.0 + t * t), sn = t * cs;
                /* A <- Jᵀ A J with J the rotation in the (p, q) plane. */
                for (int k = 0; k < 3; k++) {
                    double akp = A[k][p], akq = A[k][q];
                    A[k][p] = cs * akp - sn * akq;
                    A[k][q] = sn * akp + cs * akq;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = A[p][k], aqk = A[q][k];
                    A[p][k] = cs * apk - sn * aqk;
                    A[q][k] = sn * apk + cs * aqk;
                }
                A[p][q] = A[q][p] = 0.0;
                for (int k = 0; k < 3; k++) {
                    double vkp = V[k][p], vkq = V[k][q];
                    V[k][p] = cs * vkp - sn * vkq;
                    V[k][q] = sn * vkp + cs * vkq;
                }
                rotated = 1;
            }
        if (!rotated)
            break;
    }
    /* Increasing order (the columns of V are the eigenvectors), then the
     * third axis the cross product of the first two. */
    int o[3] = {0, 1, 2};
    for (int j = 0; j < 3; j++)
        for (int k = j + 1; k < 3; k++)
            if (A[o[k]][o[k]] < A[o[j]][o[j]]) {
                int s = o[j];
                o[j] = o[k];
                o[k] = s;
            }
    for (int j = 0; j < 3; j++) {
        val[j] = A[o[j]][o[j]];
        for (int k = 0; k < 3; k++)
            vec[j][k] = V[k][o[j]];
    }
    vec[2][0] = vec[0][1] * vec[1][2] - vec[0][2] * vec[1][1];
    vec[2][1] = vec[0][2] * vec[1][0] - vec[0][0] * vec[1][2];
    vec[2][2] = vec[0][0] * vec[1][1] - vec[0][1] * vec[1][0];
}
