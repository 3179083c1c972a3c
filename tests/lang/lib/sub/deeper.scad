deeper_value = 100;
