using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The answer of a cast: the first contact of the sphere along its segment, or its end when it met nothing.
/// </summary>
/// <param name="Hit">Whether it met something at or before its end; with <see cref="Kind"/> <see cref="SurfaceKind.None"/>, it was stopped by land that is not loaded (or off the world), or by its limit of pieces.</param>
/// <param name="Fraction">How far along the segment, 0..1, the sphere's centre is at the contact; 1 when it met nothing.</param>
/// <param name="Position">The sphere's centre there, world metres.</param>
/// <param name="Point">The point of contact, world metres: <see cref="Position"/> less the radius along <see cref="Normal"/>, on the surface (except for a sphere that started within its radius of it, and on the spec's bilinear terrain, where it is the radius along the normal below the centre); <see cref="Position"/> when it met nothing.</param>
/// <param name="Normal">The unit normal of the contact, world axes, pointing at the sphere (for a polygon met on its face, the polygon's; at an edge or a corner, from it to the centre); zero when it met nothing.</param>
/// <param name="Kind">What it met: terrain, a cell's floor, wall or ceiling, an object's floor, wall, shell or cylinder, or a mover.</param>
/// <param name="Id">Whose it is (as <see cref="SurfaceContact.Id"/>): the outdoor cell for terrain, the cell, the object's GfxObj/Setup id, or the mover's id; 0 when it met nothing.</param>
/// <param name="CellId">The cell the sphere's centre is in at <see cref="Position"/>: an indoor cell reached through portals, or the outdoor cell under it.</param>
public readonly record struct CastHit(bool Hit, float Fraction, Vector3 Position, Vector3 Point, Vector3 Normal, SurfaceKind Kind, uint Id, uint CellId);
