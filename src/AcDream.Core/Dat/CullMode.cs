namespace AcDream.Core.Dat;

/// <summary>Which faces of a <see cref="Polygon"/> exist (its "sides type"), with the values stored in the dat.</summary>
public enum CullMode
{
    /// <summary>Single-sided: only the front face, counter-clockwise seen from the front, draws and collides.</summary>
    None = 0x0,

    /// <summary>Two-sided, the back face with its own surface (<see cref="Polygon.NegSurface"/>).</summary>
    Clockwise = 0x1,

    /// <summary>Two-sided with the same surface on both faces.</summary>
    CounterClockwise = 0x2,

    /// <summary>Terrain polygons of a landblock.</summary>
    Landblock = 0x3,
}
