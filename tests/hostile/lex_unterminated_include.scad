include <abc
cube();
