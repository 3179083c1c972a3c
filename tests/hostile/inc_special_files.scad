include <.>
include </>
include </dev/null>
use </dev/null>
use <.>
cube();
