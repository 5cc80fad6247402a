// Fixture: a solver header (the target of the forbidden include).
#pragma once
