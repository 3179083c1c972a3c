// assigned twice in one file: warned, even when included twice
lib_a = 1;
lib_a = 2;
lib_b = 3;
main_a = 9;
