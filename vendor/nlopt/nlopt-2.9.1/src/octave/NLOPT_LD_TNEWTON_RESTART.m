% NLOPT_LD_TNEWTON_RESTART: Truncated Newton with restarting (local, derivative-based)
%
% See nlopt_minimize for more information.
function val = NLOPT_LD_TNEWTON_RESTART
  val = 15;
