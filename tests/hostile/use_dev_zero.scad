use </dev/zero>
cube();
