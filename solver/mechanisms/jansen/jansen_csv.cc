#include <mechanisms/jansen/jansen_csv.h>

#include <cmath>
#include <iomanip>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      double degrees(const double radians)
      {
        const double d = radians * 180. / M_PI;
        return d - 360. * std::floor(d / 360.);
      }
    } // namespace

    void write_crank_turn_csv(std::ostream &out, const std::vector<JansenState> &states)
    {
      out << "theta2_deg,x_H,y_H,vx_H,vy_H,v_H,ax_H,ay_H,a_H,"
             "theta3_deg,theta4_deg,theta5_deg,theta5p_deg,theta6_deg,theta7_deg,theta8_deg,"
             "theta8p_deg,omega3,omega4,omega5,omega6,omega7,omega8,"
             "alpha3,alpha4,alpha5,alpha6,alpha7,alpha8";
      for (const Joint j : all_joints)
        out << ",x_" << joint_name(j) << ",y_" << joint_name(j);
      out << "\n" << std::setprecision(12);

      for (const JansenState &s : states)
        {
          const LinkAngles   &a   = s.pose.angles;
          const LinkRates    &w   = s.motion.angular_velocities;
          const LinkRates    &al  = s.motion.angular_accelerations;
          const PlanarVector &h   = s.pose.positions[Joint::H];
          const PlanarVector &v   = s.motion.velocities[Joint::H];
          const PlanarVector &acc = s.motion.accelerations[Joint::H];
          // The crank angle is written unwrapped so that the last row reads 360.
          out << s.theta2 * 180. / M_PI << ',' << h.x << ',' << h.y << ',' << v.x << ',' << v.y
              << ',' << norm(v) << ',' << acc.x << ',' << acc.y << ',' << norm(acc) << ','
              << degrees(a.theta3) << ',' << degrees(a.theta4) << ',' << degrees(a.theta5) << ','
              << degrees(a.theta5p) << ',' << degrees(a.theta6) << ',' << degrees(a.theta7)
              << ',' << degrees(a.theta8) << ',' << degrees(a.theta8p) << ',' << w.link3 << ','
              << w.link4 << ',' << w.link5 << ',' << w.link6 << ',' << w.link7 << ','
              << w.link8 << ',' << al.link3 << ',' << al.link4 << ',' << al.link5 << ','
              << al.link6 << ',' << al.link7 << ',' << al.link8;
          for (const Joint j : all_joints)
            out << ',' << s.pose.positions[j].x << ',' << s.pose.positions[j].y;
          out << '\n';
        }
    }
  } // namespace jansen
} // namespace compliant
