using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Minimal portal-connection info extracted from EnvCell.CellPortals.
/// </summary>
/// <param name="TargetCellId">Full id of the neighbour cell (<c>0xXXYYCCCC</c>, same landblock), or <c>0xXXYYFFFF</c> when the portal leads outdoors.</param>
/// <param name="PortalOrigin">Centroid (mean of the vertices) of the portal polygon, landblock-local metres.</param>
/// <param name="PortalNormal">
/// Unit normal of the portal polygon, landblock-local, pointing out of this cell into the neighbour
/// (the winding normal, flipped by the portal's side flag). <see cref="Vector3.Zero"/> for a
/// degenerate (zero-area) portal polygon, which only the neighbour-floor fallback can pass.
/// </param>
public readonly record struct CellPortalInfo(
    uint TargetCellId,
    Vector3 PortalOrigin,
    Vector3 PortalNormal);
