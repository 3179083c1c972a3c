function inner_value() = "from inner";
