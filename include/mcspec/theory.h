/* mcspec theory module: declarations land with its implementation. */
#ifndef MCSPEC_THEORY_H
#define MCSPEC_THEORY_H
#endif /* MCSPEC_THEORY_H */
