/* mcspec moment module: declarations land with its implementation. */
#ifndef MCSPEC_MOMENT_H
#define MCSPEC_MOMENT_H
#endif /* MCSPEC_MOMENT_H */
