int run_demo() { return 0; }
