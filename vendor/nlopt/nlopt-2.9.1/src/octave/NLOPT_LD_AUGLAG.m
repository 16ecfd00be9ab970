% NLOPT_LD_AUGLAG: Augmented Lagrangian method (local, derivative)
%
% See nlopt_minimize for more information.
function val = NLOPT_LD_AUGLAG
  val = 30;
