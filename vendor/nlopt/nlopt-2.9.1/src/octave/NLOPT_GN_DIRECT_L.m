% NLOPT_GN_DIRECT_L: DIRECT-L (global, no-derivative)
%
% See nlopt_minimize for more information.
function val = NLOPT_GN_DIRECT_L
  val = 1;
