namespace AcDream.App.Capture;

/// <summary>A capture that cannot be used: the message names the line (1 is the header) and the field.</summary>
/// <param name="line">The line, from 1; 0 when the file itself cannot be read.</param>
/// <param name="field">The field's path in the line (<c>request.position[1]</c>); empty when the line as a whole is wrong.</param>
/// <param name="what">What is wrong.</param>
internal sealed class CaptureFormatException(int line, string field, string what)
    : Exception(line == 0 ? what : field.Length == 0 ? $"line {line}: {what}" : $"line {line}, field \"{field}\": {what}")
{
    /// <summary>The line, from 1 (0: the file).</summary>
    public int Line { get; } = line;

    /// <summary>The field's path in the line, or empty.</summary>
    public string Field { get; } = field;
}
