include </dev/zero>
cube();
