/* The C side of tests/externals/c_rendezvous. */
int rendezvous_wait(int ms);
void rendezvous_set(void);
