#include <time.h>
#include "rendezvous.h"

static volatile int flag = 0;

int rendezvous_wait(int ms) {
    struct timespec pause = {0, 1000000};
    for (int i = 0; i < ms && !flag; i++)
        nanosleep(&pause, NULL);
    return flag;
}

void rendezvous_set(void) {
    flag = 1;
}
