in_use = 1;
in_use = 2;
function in_use() = in_use;
